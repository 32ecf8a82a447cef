// What the dense lattice's shaders (lattice.glsl, lbm_step.comp,
// lbm_field.comp) and their host side (src/lbm/vulkan_solver.cpp) agree on,
// written once for both: GLSL includes this file, and so does C++. The
// layout's own constants (0-9) are in lattice_layout.glsl and
// src/lbm/lattice_memory.hpp.
#ifndef LBMSHAPE_LATTICE_INTERFACE_H
#define LBMSHAPE_LATTICE_INTERFACE_H

// Bindings of set 0 of the step and the field pass.
#define LATTICE_BINDING_IN 0      // samplerBuffer: the post-collision copy a step reads
#define LATTICE_BINDING_OMEGA 1   // samplerBuffer: 1/tau per cell
#define LATTICE_BINDING_SOURCE 2  // samplerBuffer: A of the source S = A - c X
#define LATTICE_BINDING_NEXT 3    // storage buffers [9]: the copy a step writes, one per row group
#define LATTICE_BINDING_FIELD 4   // storage buffer: X (the field pass's output; the paper's rule's X before)
#define LATTICE_BINDING_GAMMA 5   // storage buffer: gamma per cell under the paper's rule (the omega buffer)

// Specialization constants after the layout's.
#define LATTICE_SPEC_PER_CELL_OMEGA 10
#define LATTICE_SPEC_HAS_SOURCE 11
#define LATTICE_SPEC_PAPER_RULE 12

// The push constants, as a list of (type, name) for both languages.
#define LATTICE_STEP_PARAMETERS(FIELD) \
  FIELD(float, omega) /* 1/tau where it is the same in every cell */ \
  FIELD(float, decay) /* c of the source */                          \
  FIELD(float, baseScale) /* k of the source: S = k base - c X */      \
  FIELD(float, gamma0) /* the paper's rule: gamma = gamma0 + kappa */ \
  FIELD(int, writeField) /* a step also stores the X it pulled (field pass's) */ \
  FIELD(float, fieldDecay) /* ... under a source of this decay and scale */ \
  FIELD(float, fieldBaseScale)

// The push constants of the feature-preserving rule's pass
// (lbm_feature_rule.comp).
#define LATTICE_FEATURE_RULE_PARAMETERS(FIELD)                          \
  FIELD(float, gamma0) /* gamma where the field is flat */              \
  FIELD(float, kappaEdge) /* the curvature at which gamma is halved */  \
  FIELD(float, lowestGamma) /* gamma's floor: min(lowest, gamma0) */

#define LATTICE_DECLARE_FIELD(type, name) type name;

#ifdef __cplusplus
namespace lbmshape::lattice_shader {
struct StepParameters {
  LATTICE_STEP_PARAMETERS(LATTICE_DECLARE_FIELD)
};
static_assert(sizeof(StepParameters) == 7 * 4, "push constants: 7 words");
struct FeatureRuleParameters {
  LATTICE_FEATURE_RULE_PARAMETERS(LATTICE_DECLARE_FIELD)
};
static_assert(sizeof(FeatureRuleParameters) == 3 * 4, "push constants: 3 words");
}  // namespace lbmshape::lattice_shader
#endif

#endif
