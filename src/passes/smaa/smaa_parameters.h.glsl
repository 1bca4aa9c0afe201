// Mirrors photopic::SmaaParameters (passes/smaa/SmaaPass.h), std140: one block for the edge and weight steps.
layout(std140, binding = BINDING_PARAMETERS) uniform SmaaParameters {
    float uThreshold;
    float uContrastFactor;
    float uCornerRounding; // fraction kept at a detected corner; 1: no corner detection
    int uSearchSteps;
    int uDiagSteps; // 0: no diagonal patterns
    float uSubpixel; // the blend step: how far a one-pixel ridge no pattern blended moves towards its sides
    int uTilesX;     // 8 x 8 tiles per row
    int uTileCount;  // tiles in the image: the length of each part of the tile lists
    int uBlendAll;   // the blend step runs over the whole image (its input could not be copied to its output)
};

