// The testbed's analytic scene on the GPU: the GLSL twin of TestbedGeometry.cpp (intersections, albedo,
// the local shading model, the sky). Keep the two in step: the ray tracer's truths test this code.

#define TESTBED_SPHERE 0
#define TESTBED_BOX 1
#define TESTBED_CYLINDER 2
#define TESTBED_PI 3.14159265358979

// One object (TestbedRenderer.cpp's GpuPrimitive).
struct TestbedPrimitive {
    mat4 toWorld;
    mat4 toObject;
    mat4 prevToWorld;
    vec4
        shape; // x: TESTBED_* type, yzw: size (sphere radius; box half extents; cylinder radius, half height)
    vec4 albedo;   // rgb, w: checker square size (0: plain)
    vec4 albedo2;  // rgb: the checker's second colour, w: metallic
    vec4 emissive; // rgb, w: object id
    vec4 surface;  // x: roughness
};

#include "scenes/sun_disc.h.glsl"

layout(std430, binding = 0) readonly buffer TestbedPrimitives {
    TestbedPrimitive uPrimitives[];
};

// TestbedRenderer.cpp's GpuFrame.
layout(std140, binding = 0) uniform TestbedFrame {
    mat4 uView;
    mat4 uInvView;
    mat4 uProjection;     // jittered
    mat4 uViewProjection; // jittered, for the proxies
    mat4 uCurrViewProj;   // unjittered (motion)
    mat4 uPrevViewProj;   // unjittered, previous frame
    vec4 uViewport;       // width, height, 1 / width, 1 / height
    vec4 uSunDirection;   // xyz towards the sun, w: cos(angular radius)
    vec4 uSunIlluminance; // rgb, w: 1 / (pi r^2), the disc's radiance per unit illuminance
    vec4 uSkyZenith;
    vec4 uSkyHorizon;
    vec4 uGroundRadiance;
    vec4 uAmbientSky;
    vec4 uAmbientGround;
    ivec4 uFlags; // x: multiply the ambient term by uAmbientOcclusion, y: the sun term by uSunVisibility
    vec4 uAmbientOcclusionPower; // x: the exponent on the ambient visibility
};

// World-space ray through a window position (pixel units, GL origin bottom-left) with the jittered
// projection.
void testbedCameraRay(vec2 fragCoord, out vec3 origin, out vec3 direction) {
    vec2 ndc = fragCoord * uViewport.zw * 2.0 - 1.0;
    vec3 viewDir = vec3((ndc.x + uProjection[2][0]) / uProjection[0][0],
                        (ndc.y + uProjection[2][1]) / uProjection[1][1], -1.0);
    origin = uInvView[3].xyz;
    direction = normalize(mat3(uInvView) * viewDir);
}

// Precise ray/sphere (Haines, Guenther and Akenine-Moeller, Ray Tracing Gems 2019, ch. 7).
bool testbedSphere(float r, vec3 o, vec3 d, float tMin, float tMax, out float t, out vec3 n) {
    float b = -dot(o, d);
    vec3 l = o + b * d;
    float disc = r * r - dot(l, l);
    t = 0.0;
    n = vec3(0.0);
    if (disc < 0.0) {
        return false;
    }
    float c = dot(o, o) - r * r;
    float q = b + (b >= 0.0 ? sqrt(disc) : -sqrt(disc));
    float t0 = q != 0.0 ? c / q : 0.0;
    float t1 = q;
    if (t0 > t1) {
        float s = t0;
        t0 = t1;
        t1 = s;
    }
    t = t0 > tMin ? t0 : t1;
    if (!(t > tMin && t < tMax)) {
        return false;
    }
    n = (o + t * d) / r;
    return true;
}

// Slab test (Kay and Kajiya 1986).
bool testbedBox(vec3 h, vec3 o, vec3 d, float tMin, float tMax, out float t, out vec3 n) {
    vec3 safe = mix(d, vec3(1e-12), lessThan(abs(d), vec3(1e-12)));
    vec3 inv = 1.0 / safe;
    vec3 t1 = (-h - o) * inv;
    vec3 t2 = (h - o) * inv;
    vec3 lo = min(t1, t2);
    vec3 hi = max(t1, t2);
    float tNear = max(lo.x, max(lo.y, lo.z));
    float tFar = min(hi.x, min(hi.y, hi.z));
    t = 0.0;
    n = vec3(0.0);
    if (tNear > tFar) {
        return false;
    }
    int axis;
    float s;
    if (tNear > tMin) {
        t = tNear;
        axis = lo.x == tNear ? 0 : (lo.y == tNear ? 1 : 2);
        s = d[axis] > 0.0 ? -1.0 : 1.0;
    } else {
        t = tFar;
        axis = hi.x == tFar ? 0 : (hi.y == tFar ? 1 : 2);
        s = d[axis] > 0.0 ? 1.0 : -1.0;
    }
    if (!(t > tMin && t < tMax)) {
        return false;
    }
    n[axis] = s;
    return true;
}

// Capped cylinder along y.
bool testbedCylinder(float r, float h, vec3 o, vec3 d, float tMin, float tMax, out float t, out vec3 n) {
    bool found = false;
    float best = tMax;
    n = vec3(0.0);
    float a = d.x * d.x + d.z * d.z;
    if (a > 1e-12) {
        float b = o.x * d.x + o.z * d.z;
        float c = o.x * o.x + o.z * o.z - r * r;
        float disc = b * b - a * c;
        if (disc >= 0.0) {
            float s = sqrt(disc);
            for (int i = 0; i < 2; ++i) {
                float root = (-b + (i == 0 ? -s : s)) / a;
                float y = o.y + root * d.y;
                if (root > tMin && root < best && abs(y) <= h) {
                    best = root;
                    n = vec3(o.x + root * d.x, 0.0, o.z + root * d.z) / r;
                    found = true;
                    break;
                }
            }
        }
    }
    if (abs(d.y) > 1e-12) {
        for (int i = 0; i < 2; ++i) {
            float cap = i == 0 ? -h : h;
            float root = (cap - o.y) / d.y;
            float x = o.x + root * d.x;
            float z = o.z + root * d.z;
            if (root > tMin && root < best && x * x + z * z <= r * r) {
                best = root;
                n = vec3(0.0, cap > 0.0 ? 1.0 : -1.0, 0.0);
                found = true;
            }
        }
    }
    t = best;
    return found;
}

// Nearest hit of a world ray with primitive p; object-space point and normal, world normal.
bool testbedIntersect(TestbedPrimitive p, vec3 origin, vec3 direction, float tMin, float tMax, out float t,
                      out vec3 objectPoint, out vec3 objectNormal, out vec3 worldNormal) {
    vec3 o = (p.toObject * vec4(origin, 1.0)).xyz;
    vec3 d = mat3(p.toObject) * direction;
    int type = int(p.shape.x);
    bool found;
    if (type == TESTBED_SPHERE) {
        found = testbedSphere(p.shape.y, o, d, tMin, tMax, t, objectNormal);
    } else if (type == TESTBED_BOX) {
        found = testbedBox(p.shape.yzw, o, d, tMin, tMax, t, objectNormal);
    } else {
        found = testbedCylinder(p.shape.y, p.shape.z, o, d, tMin, tMax, t, objectNormal);
    }
    objectPoint = o + t * d;
    worldNormal = found ? normalize(mat3(p.toWorld) * objectNormal) : vec3(0.0);
    return found;
}

vec3 testbedAlbedo(TestbedPrimitive p, vec3 objectPoint, vec3 objectNormal) {
    float size = p.albedo.w;
    if (size <= 0.0) {
        return p.albedo.rgb;
    }
    vec3 q = objectPoint / size;
    if (int(p.shape.x) == TESTBED_BOX) {
        q *= vec3(1.0) - abs(objectNormal); // a box face: its two tangent axes
    }
    float sum = floor(q.x) + floor(q.y) + floor(q.z);
    float parity = sum - 2.0 * floor(0.5 * sum);
    return parity < 0.5 ? p.albedo.rgb : p.albedo2.rgb;
}

// The local shading model (TestbedGeometry.h); visibilities 1 unless a lighting stage supplies them.
vec3 testbedShade(TestbedPrimitive p, vec3 objectPoint, vec3 objectNormal, vec3 n, float sunVisibility,
                  float ambientVisibility) {
    vec3 ambient = mix(uAmbientGround.rgb, uAmbientSky.rgb, 0.5 + 0.5 * n.y);
    float nl = max(dot(n, uSunDirection.xyz), 0.0);
    vec3 diffuse = testbedAlbedo(p, objectPoint, objectNormal) * (1.0 - p.albedo2.w);
    return diffuse * (uSunIlluminance.rgb * (nl * sunVisibility) + ambient * ambientVisibility) / TESTBED_PI +
           p.emissive.rgb;
}

// The sky along d, seen through a pixel `pixelAngle` radians across: the sun's disc by the share of the pixel
// it covers (scenes/sun_disc.h.glsl). The ray tracer's skyRadiance is the same sky at a point; averaged over
// its samples in a pixel it is this.
vec3 testbedSky(vec3 d, float pixelAngle) {
    vec3 l = d.y >= 0.0 ? mix(uSkyHorizon.rgb, uSkyZenith.rgb, sqrt(d.y)) : uGroundRadiance.rgb;
    return l + uSunIlluminance.rgb * uSunIlluminance.w *
                   sunDiscCoverage(d, uSunDirection.xyz, uSunDirection.w, pixelAngle);
}

// UV displacement current minus previous of homogeneous points (w = 0: a direction, the sky).
vec2 testbedMotion(vec4 now, vec4 before) {
    vec4 a = uCurrViewProj * now;
    vec4 b = uPrevViewProj * before;
    return 0.5 * (a.xy / a.w - b.xy / b.w);
}
