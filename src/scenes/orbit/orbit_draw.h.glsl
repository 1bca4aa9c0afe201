// The mesh shaders' per-draw block (OrbitRenderer.cpp's GpuDraw).
layout(std140, binding = 1) uniform OrbitDraw {
    mat4 uModel;          // model -> world now
    mat4 uPrevModel;      // model -> world one frame earlier (the ship's own motion)
    mat4 uNormalMatrix;   // upper 3x3: normals model -> world (renormalised)
    vec4 uBaseColorFactor; // linear RGBA
    vec4 uEmissiveFactor;  // rgb linear, w: alpha cutoff (0: opaque)
    vec4 uSurface;         // metallic, roughness, normal scale (0: no normal map), occlusion strength
    vec4 uEnv;             // x: the material's IBL baseline (0: no IBL), y: object id, z: double-sided
};
