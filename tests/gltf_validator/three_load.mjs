// Loads one .glb file with three.js's GLTFLoader and its meshopt decoder,
// as a web viewer would, and prints what it sees as one JSON object:
// {"meshes", "triangles", "min", "max" (the scene's world bounding box),
// "animations"}. Exits 1 when three.js cannot load the file.
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
  let meshes = 0, triangles = 0;
  const box = new THREE.Box3();
  gltf.scene.updateMatrixWorld(true);
  gltf.scene.traverse((node) => {
    if (!node.isMesh) return;
    meshes++;
    const geometry = node.geometry;
    triangles += (geometry.index ? geometry.index.count : geometry.attributes.position.count) / 3;
    geometry.computeBoundingBox();
    box.union(geometry.boundingBox.clone().applyMatrix4(node.matrixWorld));
  });
  console.log(JSON.stringify({ meshes, triangles, min: box.min.toArray(), max: box.max.toArray(),
                               animations: gltf.animations.length }));
}, (error) => {
  console.error(`three.js cannot load ${process.argv[2]}: ${error.message ?? error}`);
  process.exit(1);
});
