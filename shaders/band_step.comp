#version 450
#extension GL_GOOGLE_include_directive : require
// A step of the narrow band, or its field pass (band_step.glsl).
#include "band_step.glsl"
