// Screen-space contact shadows: a short ray march through the depth buffer from each surface point towards
// the sun, one invocation per pixel. References: Graham Aldridge, "Inside Bend Screen Space Shadows" (Bend
// Studio, 2023) for the screen-space march towards a light; McGuire & Mara 2014, "Efficient GPU Screen-Space
// Ray Tracing", for depth samples as surfaces of a finite thickness; Jimenez 2014, "Next Generation Post
// Processing in Call of Duty: Advanced Warfare", for interleaved gradient noise.
//
// Output: this frame's sun visibility in [0, 1] (1: nothing within contactShadows.distance towards the sun;
// 0 where the surface faces away from the sun, as a ray tracer measures it; 1 for the sky and for objects a
// mask leaves out), and optionally the steps the march took.
#include "passes/contactshadows/contact_shadows_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2, r32f) uniform readonly image2D uLinearDepth; // +inf: sky
layout(binding = 3, rgba32f) uniform readonly image2D uSurface; // view normal, plane constant (0: no surface)
layout(binding = 0, r16f) uniform writeonly image2D uRaw;
layout(binding = 1, r8) uniform writeonly image2D uStepsTaken;

// A perspective projection (its view rays meet at the eye and its near plane is z = const): a define, a
// program per kind. There a sample plane's depth along a view ray r = (x, y, -1) is c / dot(n, r), a third of
// the arithmetic of the general line-plane intersection the orthographic program keeps.
const bool kPerspective = CONTACT_SHADOWS_PERSPECTIVE != 0;

// The last quarter of the ray fades out, so the shadow does not end in a hard line where the march stops.
const float kFadeFraction = 0.25;
// A depth sample's plane is trusted only when the view ray meets it at more than this cosine; flatter, the
// sample is a silhouette seen edge-on and is skipped.
const float kGrazingCos = 0.01;
// Depth differences below this fraction of the depth are precision (depth buffer, half-float normals).
const float kDepthEpsilon = 2e-4;

// Interleaved gradient noise (Jimenez 2014) for the start offset, moved each frame along the golden-ratio
// sequence so that every pixel's offsets fill [0, 1) evenly over frames for the accumulation.
float startOffset(ivec2 p, uint frame) {
    float ign = fract(52.9829189 * fract(dot(vec2(p), vec2(0.06711056, 0.00583715))));
    return fract(ign + 0.61803399 * float(frame % 64u));
}

bool hasSurface(vec4 surface) { return dot(surface.xyz, surface.xyz) > 0.5; }

// Depth, along the view ray (a, d: its point at NDC z = -1 and the step to NDC z = 0), of a sample's plane
// (unit normal, constant): the sample's surface continued to where the ray's point is, instead of the
// sample's depth at its texel centre (which at a grazing angle differs by many thicknesses within one
// pixel). Negative when the plane is seen edge-on (a silhouette texel, whose plane says nothing about its
// neighbourhood).
float surfaceDepthAt(vec3 a, vec3 d, vec4 plane) {
    float denom = dot(d, plane.xyz);
    float depth = -(a.z + ((plane.w - dot(a, plane.xyz)) / denom) * d.z);
    return denom * denom <= kGrazingCos * kGrazingCos * dot(d, d) ? -1.0 : depth;
}

// surfaceDepthAt for a perspective projection: the view ray through the eye along r (r.z = -1, so the
// parameter along r is the depth), rr = dot(r, r).
float surfaceDepthAlong(vec3 r, float rr, vec4 plane) {
    float denom = dot(r, plane.xyz);
    return denom * denom <= kGrazingCos * kGrazingCos * rr ? -1.0 : plane.w / denom;
}

// The perspective view ray (r.z = -1) through NDC (x, y): the near plane's point scaled to depth 1.
vec3 perspectiveRay(vec2 ndc) {
    vec2 xy = uRayNear[0].xy + ndc.x * uRayNear[1].xy + ndc.y * uRayNear[2].xy;
    return vec3(xy * (1.0 / -uRayNear[0].z), -1.0);
}

float fade(float t, vec2 window) {
    float along = clamp((uDistance - t) / (kFadeFraction * uDistance), 0.0, 1.0);
    vec2 edge = min(window, uFullSize - window);
    return along * clamp(min(edge.x, edge.y) / uEdgeFade, 0.0, 1.0);
}

// March from p (view-space point `origin`) towards the sun; returns the occlusion in [0, 1] (the fade at the
// first hit) and the steps taken.
//
// Each sample's texel stands for the plane through its point with its normal. The ray is occluded there
// when it lies behind that surface now, and either started in front of it (it crossed the surface on the
// way: the contact case, where the crossing often happens while the ray is still inside its own pixel) or
// lies behind it by less than the thickness (the surface's assumed depth).
float march(ivec2 p, vec3 origin, out float taken) {
    vec3 sun = uSunView.xyz;
    vec4 clip0 = uProjection * vec4(origin, 1.0);
    vec4 clipStep = uProjection * vec4(sun, 0.0);
    float stepLength = uDistance / float(uSteps);
    float jitter = startOffset(p, uFrame);
    vec3 originA, originB;
    viewRay(vec2(p) + 0.5, originA, originB);
    vec3 originD = originB - originA;
    vec3 originR = perspectiveRay((vec2(p) + 0.5) / uFullSize * 2.0 - 1.0);
    float originRR = dot(originR, originR);
    float originDepth = -origin.z;
    // The view ray through NDC (x, y) is a = near[0] + x near[1] + y near[2] on, along d = d0 + x d1 + y d2.
    vec3 d0 = uRayFar[0].xyz - uRayNear[0].xyz;
    vec3 d1 = uRayFar[1].xyz - uRayNear[1].xyz;
    vec3 d2 = uRayFar[2].xyz - uRayNear[2].xyz;
    taken = 0.0;
    float hitT = -1.0; // the first hit's t and window position (the fade is worked out once, after the march)
    vec2 hitWindow = vec2(0.0);
    bool done = false; // hit, or off screen from there on (the ray's image is a line: it does not come back)
    for (int i = 0; i < uSteps; ++i) {
        float t = (float(i) + jitter) * stepLength;
        vec4 clip = clip0 + t * clipStep; // clip space is linear along the ray
        vec2 ndc = clip.xy / clip.w;
        vec2 window = (ndc * 0.5 + 0.5) * uFullSize;
        // Behind the camera or off screen: nothing more is known.
        bool onScreen =
            clip.w > 0.0 && all(greaterThanEqual(window, vec2(0.0))) && all(lessThan(window, uFullSize));
        done = done || !onScreen;
        vec4 plane = imageLoad(uSurface, clamp(ivec2(window), ivec2(0), ivec2(uFullSize) - 1));
        float here, atStart;
        if (kPerspective) {
            vec3 r = perspectiveRay(ndc);
            here = surfaceDepthAlong(r, dot(r, r), plane);
            atStart = surfaceDepthAlong(originR, originRR, plane);
        } else {
            vec3 a = uRayNear[0].xyz + ndc.x * uRayNear[1].xyz + ndc.y * uRayNear[2].xyz;
            here = surfaceDepthAt(a, d0 + ndc.x * d1 + ndc.y * d2, plane);
            atStart = surfaceDepthAt(originA, originD, plane);
        }
        float behind = -(origin.z + t * sun.z) - here;
        float behindAtStart = originDepth - atStart;
        bool hit = hasSurface(plane) && here > 0.0 && atStart > 0.0 && behind > kDepthEpsilon * here &&
                   (behindAtStart <= 0.0 || behind < uThickness);
        bool first = !done && hit;
        hitT = first ? t : hitT;
        hitWindow = first ? window : hitWindow;
        taken = done ? taken : float(i + 1);
        done = done || hit;
    }
    return hitT >= 0.0 ? fade(hitT, hitWindow) : 0.0;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    float visibility = 1.0;
    float taken = 0.0;
    vec4 plane = imageLoad(uSurface, p);
    if (hasSurface(plane)) {
        if (dot(plane.xyz, uSunView.xyz) <= 0.0) {
            visibility = 0.0; // the surface itself hides the sun
        } else {
            vec3 origin = viewPositionAt(vec2(p) + 0.5, imageLoad(uLinearDepth, p).r);
            float occlusion = march(p, origin, taken);
            // Strength scales the occlusion, then clamps: above 1 a hit stays black further into the fade.
            visibility = 1.0 - clamp(uStrength * occlusion, 0.0, 1.0);
        }
    }
    imageStore(uRaw, p, vec4(visibility));
    if (uWriteSteps != 0) {
        imageStore(uStepsTaken, p, vec4(taken / float(uSteps)));
    }
}
