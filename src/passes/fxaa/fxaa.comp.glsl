// FXAA on the display-referred image (its edge test expects perceptual values), written from the description
// of FXAA 3.11's quality path (T. Lottes, "FXAA", NVIDIA whitepaper, 2009, and the FXAA 3.11 source comments,
// 2011):
//  1. local contrast of the 4-neighbourhood; below max(edgeThresholdMin, edgeThreshold * max luma) the pixel
//     is left exactly as it is (flat areas never change);
//  2. the edge is horizontal or vertical by comparing second differences over the 3x3 neighbourhood;
//  3. the side of the edge with the steeper gradient is chosen and the search starts half a pixel towards it;
//  4. both ends of the edge are searched along it with growing steps (1, 1.5, 2, 4, 12 pixels) until the
//     luma leaves the average of the pair by a quarter of the gradient;
//  5. the pixel is re-sampled across the edge by its position along the span (nearer end wins), or by the
//     sub-pixel amount (the 3x3 low-pass contrast, squared, times `subpix`) when that is larger.
// Luma is Rec.709 weights on the sRGB-encoded (perceptual) values, as FXAA expects. A compute pass (8x8
// groups, one pixel each, image store): on GPUs whose raster units are a small part of the chip it runs
// at the memory's pace where a full-screen triangle does not.
#include "passes/common/color.h.glsl"
#include "passes/common/display_format.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
// Mirrors photopic::FxaaParameters (passes/fxaa/FxaaPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform FxaaParameters {
    vec2 uTexel; // 1 / size
    float uSubpix;
    float uEdgeThreshold;
    float uEdgeThresholdMin;
};


const int kSteps = 5;
const float kStepSizes[kSteps] = float[](1.0, 1.5, 2.0, 4.0, 12.0);

float lumaAt(vec2 uv) {
    return luma709(textureLod(uInput, uv, 0.0).rgb);
}

float lumaOffset(vec2 uv, vec2 offset) {
    return lumaAt(uv + offset * uTexel);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) * uTexel;
    vec4 centre = texelFetch(uInput, p, 0);
    float lumaM = luma709(centre.rgb);
    // "North" is -y (one row towards v = 0), "west" is -x.
    float lumaN = lumaOffset(uv, vec2(0.0, -1.0));
    float lumaS = lumaOffset(uv, vec2(0.0, 1.0));
    float lumaW = lumaOffset(uv, vec2(-1.0, 0.0));
    float lumaE = lumaOffset(uv, vec2(1.0, 0.0));

    float rangeMax = max(lumaM, max(max(lumaN, lumaS), max(lumaW, lumaE)));
    float rangeMin = min(lumaM, min(min(lumaN, lumaS), min(lumaW, lumaE)));
    float range = rangeMax - rangeMin;
    if (range < max(uEdgeThresholdMin, rangeMax * uEdgeThreshold)) {
        imageStore(uOutput, p, centre);
        return;
    }

    float lumaNW = lumaOffset(uv, vec2(-1.0, -1.0));
    float lumaNE = lumaOffset(uv, vec2(1.0, -1.0));
    float lumaSW = lumaOffset(uv, vec2(-1.0, 1.0));
    float lumaSE = lumaOffset(uv, vec2(1.0, 1.0));

    // Sub-pixel aliasing: how far the pixel stands out of its 3x3 low-pass, shaped by a smoothstep, squared.
    float lowPass = (2.0 * (lumaN + lumaS + lumaW + lumaE) + lumaNW + lumaNE + lumaSW + lumaSE) / 12.0;
    float subpixA = clamp(abs(lowPass - lumaM) / range, 0.0, 1.0);
    float subpixB = (-2.0 * subpixA + 3.0) * subpixA * subpixA;
    float subpixH = subpixB * subpixB * uSubpix;

    // Second differences across rows (a horizontal edge) against across columns (a vertical edge).
    float edgeHorz = abs(lumaNW - 2.0 * lumaW + lumaSW) + 2.0 * abs(lumaN - 2.0 * lumaM + lumaS) +
                     abs(lumaNE - 2.0 * lumaE + lumaSE);
    float edgeVert = abs(lumaNW - 2.0 * lumaN + lumaNE) + 2.0 * abs(lumaW - 2.0 * lumaM + lumaE) +
                     abs(lumaSW - 2.0 * lumaS + lumaSE);
    bool horzSpan = edgeHorz >= edgeVert;

    // Across the edge: N/S for a horizontal edge, W/E for a vertical one.
    float lumaNeg = horzSpan ? lumaN : lumaW;
    float lumaPos = horzSpan ? lumaS : lumaE;
    float gradientNeg = abs(lumaNeg - lumaM);
    float gradientPos = abs(lumaPos - lumaM);
    bool pairNeg = gradientNeg >= gradientPos;
    float gradientScaled = 0.25 * max(gradientNeg, gradientPos);
    float lumaAvg = 0.5 * (lumaM + (pairNeg ? lumaNeg : lumaPos));
    float lengthSign = (pairNeg ? -1.0 : 1.0) * (horzSpan ? uTexel.y : uTexel.x);

    // Start half a pixel towards the chosen side, then walk both ways along the edge.
    vec2 posB = uv + (horzSpan ? vec2(0.0, 0.5 * lengthSign) : vec2(0.5 * lengthSign, 0.0));
    vec2 along = horzSpan ? vec2(uTexel.x, 0.0) : vec2(0.0, uTexel.y);
    vec2 posN = posB;
    vec2 posP = posB;
    float endN = 0.0;
    float endP = 0.0;
    bool doneN = false;
    bool doneP = false;
    for (int i = 0; i < kSteps && !(doneN && doneP); ++i) {
        if (!doneN) {
            posN -= along * kStepSizes[i];
            endN = lumaAt(posN) - lumaAvg;
            doneN = abs(endN) >= gradientScaled;
        }
        if (!doneP) {
            posP += along * kStepSizes[i];
            endP = lumaAt(posP) - lumaAvg;
            doneP = abs(endP) >= gradientScaled;
        }
    }

    float dstN = horzSpan ? uv.x - posN.x : uv.y - posN.y;
    float dstP = horzSpan ? posP.x - uv.x : posP.y - uv.y;
    bool directionN = dstN < dstP;
    float dst = min(dstN, dstP);
    float spanLength = dstN + dstP;
    // Only blend when the nearer end moves away from the average in the opposite sense from this pixel:
    // that end is where the edge's step actually lies.
    bool centreBelow = lumaM - lumaAvg < 0.0;
    bool goodSpan = ((directionN ? endN : endP) < 0.0) != centreBelow;
    float pixelOffset = goodSpan ? 0.5 - dst / spanLength : 0.0;
    float offset = max(pixelOffset, subpixH);

    vec2 finalUv = uv + (horzSpan ? vec2(0.0, offset * lengthSign) : vec2(offset * lengthSign, 0.0));
    imageStore(uOutput, p, vec4(onDisplayCode(textureLod(uInput, finalUv, 0.0).rgb), 1.0));
}
