// What the surface shaders (render_surface.vert, render_surface.frag) and
// their host side (src/render/) agree on, written once for both: GLSL
// includes this file, and so does C++ (src/render/shading.hpp evaluates the
// same light on the CPU, the reference the pictures are tested against).
//
// The light is fixed, so that pictures of different runs compare: a
// directional key light from the viewer's upper left, an ambient term, and a
// little Blinn-Phong highlight, all in view space (x right, y up, z towards
// the viewer). Surfaces are lit from both sides, as scans and frames may be
// open or inside out.
#ifndef LBMSHAPE_RENDER_INTERFACE_H
#define LBMSHAPE_RENDER_INTERFACE_H

// Vertex attributes: one interleaved buffer of RENDER_VERTEX_FLOATS floats
// per vertex (position relative to the framing's centre, unit normal, RGB colour
// as it is written to the picture, 0..1).
#define RENDER_LOCATION_POSITION 0
#define RENDER_LOCATION_NORMAL 1
#define RENDER_LOCATION_COLOUR 2
#define RENDER_VERTEX_FLOATS 9

// Push constants: two column-major 4x4 matrices, clip from centred
// position (the orthographic camera) and view from centred (its rotation,
// for the normals).
#define RENDER_PUSH_BYTES 128

// Specialization constant: 1 for the wireframe's line pass.
#define RENDER_SPEC_LINES 0

// The light (view space; the direction points from the surface to the light,
// (-0.45, 0.55, 0.70) normalised).
#define RENDER_LIGHT_X (-0.4511)
#define RENDER_LIGHT_Y (0.5514)
#define RENDER_LIGHT_Z (0.7018)
#define RENDER_AMBIENT 0.28
#define RENDER_DIFFUSE 0.72
#define RENDER_SPECULAR 0.18
#define RENDER_SHININESS 40.0
// The wireframe's lines, and the background.
#define RENDER_LINE_RGB 0.12, 0.13, 0.16
#define RENDER_BACKGROUND_RGB 1.0, 1.0, 1.0

#endif
