#version 450
#extension GL_GOOGLE_include_directive : require
// Surface pictures: the light of render_interface.h, evaluated per pixel;
// src/render/shading.hpp is the same formula on the CPU.
#include "render_interface.h"

layout(constant_id = RENDER_SPEC_LINES) const bool lines = false;

layout(location = 0) in vec3 viewNormal;
layout(location = 1) in vec3 surfaceColour;
layout(location = 0) out vec4 pixel;

void main()
{
  if (lines) {
    pixel = vec4(RENDER_LINE_RGB, 1.0);
    return;
  }
  vec3 n = normalize(viewNormal);
  // Lit from both sides: a normal facing away shows the back of the surface.
  if (n.z < 0.0) n = -n;
  const vec3 light = vec3(RENDER_LIGHT_X, RENDER_LIGHT_Y, RENDER_LIGHT_Z);
  const vec3 halfway = normalize(light + vec3(0.0, 0.0, 1.0));
  float diffuse = max(dot(n, light), 0.0);
  float specular = pow(max(dot(n, halfway), 0.0), RENDER_SHININESS);
  vec3 lit = surfaceColour * (RENDER_AMBIENT + RENDER_DIFFUSE * diffuse) + RENDER_SPECULAR * specular;
  pixel = vec4(min(lit, vec3(1.0)), 1.0);
}
