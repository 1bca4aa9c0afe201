// The angle a fragment's view direction `d` turns through from one pixel to the next (fragment shaders only:
// screen-space derivatives).
float pixelAngleOf(vec3 d) {
    return 0.5 * (length(dFdx(d)) + length(dFdy(d)));
}
