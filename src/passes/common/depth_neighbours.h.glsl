// A surface's step to its neighbouring pixel, from linear depths: for normals reconstructed from the depth.
// The including shader declares the linear depth image uLinearDepth (r32f), uFullSize (pixels), validDepth()
// and viewPositionAt(window, z).
#ifndef PHOTOPIC_DEPTH_NEIGHBOURS_H_GLSL
#define PHOTOPIC_DEPTH_NEIGHBOURS_H_GLSL

// The view-space step from p's point (centre, at depth z) towards its neighbour along +o, taken from
// whichever of p + o and p - o lies nearer z in depth (most likely the same surface); false where neither is
// a valid depth inside the image.
bool nearerNeighbourStep(ivec2 p, ivec2 o, vec3 centre, float z, out vec3 towards) {
    ivec2 size = ivec2(uFullSize);
    ivec2 a = clamp(p + o, ivec2(0), size - 1);
    ivec2 b = clamp(p - o, ivec2(0), size - 1);
    float za = imageLoad(uLinearDepth, a).r;
    float zb = imageLoad(uLinearDepth, b).r;
    bool useA = validDepth(za) && a != p && (!validDepth(zb) || b == p || abs(za - z) <= abs(zb - z));
    bool useB = !useA && validDepth(zb) && b != p;
    towards = useA ? viewPositionAt(vec2(a) + 0.5, za) - centre
                : useB ? centre - viewPositionAt(vec2(b) + 0.5, zb) : vec3(0.0);
    return useA || useB;
}

#endif
