// How GTAO's surface texture holds a normal: three signed 10-bit fields.
#ifndef PHOTOPIC_GTAO_NORMAL_H_GLSL
#define PHOTOPIC_GTAO_NORMAL_H_GLSL

// A normal as three signed 10-bit fields (x in bits 0-9, y 10-19, z 20-29) of the direction scaled so that
// its largest component is +-511: decoded by three shifts (each sample of the search reads one), and no
// reader needs its length (the plane cut is the same for any positive scale; the rest normalize).
uint packNormal10(vec3 n) {
    ivec3 q = ivec3(round(n * (511.0 / max(max(abs(n.x), abs(n.y)), abs(n.z)))));
    return uint(q.x & 1023) | (uint(q.y & 1023) << 10) | (uint(q.z & 1023) << 20);
}

vec3 unpackNormal10(uint bits) { return vec3(ivec3(uvec3(bits << 22, bits << 12, bits << 2)) >> 22); }

#endif
