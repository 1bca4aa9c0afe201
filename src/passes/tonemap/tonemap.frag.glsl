// The single tone mapping of the frame (DESIGN.md step 9) with the sRGB output transform and dither.
// Reads the scene-referred colour, multiplies by the frame's exposure (GPU exposure state), applies the curve
// (passes/tonemap/tonecurves.h.glsl mirrors core/ToneCurves.cpp), encodes sRGB, dithers by +-1 LSB (TPDF).
// With OUTPUT_SCENE defined it stops before the curve and writes the exposed scene-referred value (EXR output).
#include "passes/common/color.h.glsl"
#include "passes/common/exposure.h.glsl"
#include "passes/common/noise.h.glsl"
#include "passes/common/sanitize.h.glsl"
#include "passes/tonemap/tonecurves.h.glsl"

layout(binding = 0) uniform sampler2D uScene;
uniform int uMode;
uniform float uWhitePoint;
uniform int uAgxLook;
uniform int uDither;
uniform uint uFrame;

layout(location = 0) out vec4 oColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    // Sanitised here as well: on the LDR path this is where the pipeline first reads the host's colour.
    vec3 c = sanitize(texelFetch(uScene, p, 0).rgb) * gExposure.exposure;
#ifdef OUTPUT_SCENE
    oColor = vec4(c, 1.0);
#else
    vec3 display = srgbEncode(toneMap(uMode, c, uWhitePoint, uAgxLook));
    if (uDither != 0) {
        display += vec3(triangularNoise(p, uFrame, 0u), triangularNoise(p, uFrame, 1u),
                        triangularNoise(p, uFrame, 2u)) * (1.0 / 255.0);
    }
    oColor = vec4(clamp(display, 0.0, 1.0), 1.0);
#endif
}
