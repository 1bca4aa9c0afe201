// The share of a pixel the sun's disc covers, for the scenes' skies: a disc of angular radius acos(cosRadius)
// around `sun`, seen along the unit direction `d` through a pixel `pixelAngle` radians across. A hard test of
// the pixel's centre draws the disc as a block of whole pixels; the share, linear across one pixel of the
// edge, draws it round at any size and keeps its energy (a disc's area in pixels, to the edge's curvature).
float sunDiscCoverage(vec3 d, vec3 sun, float cosRadius, float pixelAngle) {
    // The angle between d and the sun, accurate near 0 where acos(dot) is not.
    float angle = atan(length(cross(d, sun)), dot(d, sun));
    float radius = acos(clamp(cosRadius, -1.0, 1.0));
    return clamp((radius - angle) / max(pixelAngle, 1e-6) + 0.5, 0.0, 1.0);
}

