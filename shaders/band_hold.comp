#version 450
#extension GL_GOOGLE_include_directive : require
// A step of the bricks held whole, or their field pass: every cell pulls
// from itself (band_step.glsl).
#define BAND_HOLD_ONLY
#include "band_step.glsl"
