// Depth only: the rasteriser writes the depth, no colour target is attached.

void main() {}
