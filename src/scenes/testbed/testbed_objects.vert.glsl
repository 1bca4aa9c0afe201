// Each primitive's bounding box, rasterised as a proxy (instance = primitive): the fragment shader ray-casts
// the exact shape inside it. Any ray that hits the shape crosses the box, so every pixel whose centre sees
// the shape gets a fragment (both faces are drawn, no culling).
#include "testbed_shading.h.glsl"

flat out int vPrimitive;

const int kCorners[36] = int[36](0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2,
                                 3, 0, 3, 1, 4, 5, 7, 4, 7, 6);

void main() {
    TestbedPrimitive p = uPrimitives[gl_InstanceID];
    int type = int(p.shape.x);
    vec3 extent = type == TESTBED_SPHERE ? vec3(p.shape.y)
                  : type == TESTBED_BOX  ? p.shape.yzw
                                         : vec3(p.shape.y, p.shape.z, p.shape.y);
    extent = extent * 1.01 + 0.002; // margin: the proxy must contain the shape after rounding
    int c = kCorners[gl_VertexID];
    vec3 corner = vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1) * 2.0 - 1.0;
    vPrimitive = gl_InstanceID;
    gl_Position = uViewProjection * (p.toWorld * vec4(corner * extent, 1.0));
}
