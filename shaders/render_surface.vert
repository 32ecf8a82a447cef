#version 450
#extension GL_GOOGLE_include_directive : require
// Surface pictures: the vertex stage of an orthographic camera. Normals go to
// view space for the fixed light of render_interface.h.
#include "render_interface.h"

layout(location = RENDER_LOCATION_POSITION) in vec3 position;
layout(location = RENDER_LOCATION_NORMAL) in vec3 normal;
layout(location = RENDER_LOCATION_COLOUR) in vec3 colour;

layout(push_constant) uniform Camera {
  mat4 clipFromCentred;
  mat4 viewFromCentred;
};

layout(location = 0) out vec3 viewNormal;
layout(location = 1) out vec3 surfaceColour;

void main()
{
  gl_Position = clipFromCentred * vec4(position, 1.0);
  viewNormal = mat3(viewFromCentred) * normal;
  surfaceColour = colour;
}
