// A metering workgroup's histogram bins and extremes in shared memory, cleared before the group's first
// barrier and merged into the frame's (metering_buffers.h.glsl) after its last: one global atomic per
// non-empty bin, one pair for the extremes. For 16x16 groups (one bin per invocation).
#ifndef PHOTOPIC_METERING_GROUP_H_GLSL
#define PHOTOPIC_METERING_GROUP_H_GLSL

shared uint sBins[256];
shared uint sMinBits; // bits of the group's smallest meterable L (positive floats order as their bits)
shared uint sMaxBits; // bits of its largest; 0: none

// Invocation `li` clears bin li when the group bins (`bins`); invocation 0 clears the extremes.
void clearGroupTallies(uint li, bool bins) {
    if (bins) {
        sBins[li] = 0u;
    }
    if (li == 0u) {
        sMinBits = 0xffffffffu;
        sMaxBits = 0u;
    }
}

// Invocation `li` adds bin li to the frame's.
void mergeGroupBin(uint li) {
    if (sBins[li] != 0u) {
        atomicAdd(gBins[li], sBins[li]);
    }
}

// One invocation of the group merges its extremes into the frame's.
void mergeGroupExtremes() {
    if (sMaxBits != 0u) {
        atomicMin(gMinBits, sMinBits);
        atomicMax(gMaxBits, sMaxBits);
    }
}

#endif // PHOTOPIC_METERING_GROUP_H_GLSL
