// Loads one .glb file with three.js's GLTFLoader and its meshopt decoder,
// as a web viewer would, and prints what it sees as one JSON object:
// {"meshes", "triangles", "min", "max" (the scene's world bounding box),
// "animations", "coloured" (meshes with vertex colours), "colourRange"
// ([min, max] over their components)}. Exits 1 when three.js cannot load the file.
//
//   node three_load.mjs FILE.glb
import { readFile } from 'node:fs/promises';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/examples/jsm/libs/meshopt_decoder.module.js';

const bytes = await readFile(process.argv[2]);
const loader = new GLTFLoader();
loader.setMeshoptDecoder(MeshoptDecoder);
loader.parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), '', (gltf) => {
  let meshes = 0, triangles = 0, coloured = 0;
  const colourRange = [Infinity, -Infinity];
  const box = new THREE.Box3();
  gltf.scene.updateMatrixWorld(true);
  gltf.scene.traverse((node) => {
    if (!node.isMesh) return;
    meshes++;
    const geometry = node.geometry;
    triangles += (geometry.index ? geometry.index.count : geometry.attributes.position.count) / 3;
    const colour = geometry.attributes.color;
    if (colour) {
      coloured++;
      for (let i = 0; i < colour.count; i++)
        for (const value of [colour.getX(i), colour.getY(i), colour.getZ(i)]) {
          colourRange[0] = Math.min(colourRange[0], value);
          colourRange[1] = Math.max(colourRange[1], value);
        }
    }
    geometry.computeBoundingBox();
    box.union(geometry.boundingBox.clone().applyMatrix4(node.matrixWorld));
  });
  console.log(JSON.stringify({ meshes, triangles, min: box.min.toArray(), max: box.max.toArray(),
                               animations: gltf.animations.length, coloured, colourRange }));
}, (error) => {
  console.error(`three.js cannot load ${process.argv[2]}: ${error.message ?? error}`);
  process.exit(1);
});
