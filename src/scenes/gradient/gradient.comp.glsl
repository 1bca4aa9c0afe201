// Procedural sky gradient + sun disc, scene-linear Rec.709. v runs up (GL texture space).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) writeonly uniform image2D uOutput;
uniform vec2 uSun;           // sun centre in UV (y up)
uniform float uSunRadius;    // in image heights
uniform float uSunLuminance;
uniform float uSkyLuminance;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) / vec2(size);
    float aspect = float(size.x) / float(size.y);
    // Sky: brighter and bluer towards the zenith; ground: a dim green-brown, 1/20 of the sky.
    vec3 sky = uSkyLuminance * mix(vec3(0.9, 0.8, 0.7), vec3(0.35, 0.55, 1.0), smoothstep(0.4, 1.0, uv.y));
    vec3 ground = uSkyLuminance * 0.05 * vec3(0.35, 0.3, 0.18);
    vec3 c = uv.y > 0.4 ? sky : ground;
    // Sun disc with a soft limb, only above the horizon.
    float d = length((uv - uSun) * vec2(aspect, 1.0));
    float disc = 1.0 - smoothstep(uSunRadius * 0.8, uSunRadius, d);
    c += (uv.y > 0.4 ? disc : 0.0) * uSunLuminance * vec3(1.0, 0.93, 0.82);
    imageStore(uOutput, p, vec4(c, 1.0));
}
