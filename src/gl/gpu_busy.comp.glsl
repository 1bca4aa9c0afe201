// Untimed GPU work for `photopic bench --queue-ahead`: a chain of dependent multiply-adds per invocation, as
// long as uIterations says, in as many groups as the host dispatches, run before a timed frame so the GPU is
// still busy with it while the CPU submits the frame. The frame's commands are then all queued when the GPU
// reaches them, and its timestamps hold the GPU's own work without the gaps where it waits for the CPU.
// uNever is a value the chain never reaches (the host passes -1): the store it guards keeps the chain from
// being optimised away, and nothing is written.
layout(local_size_x = 64) in;

layout(location = 0) uniform uint uIterations;
layout(location = 1) uniform float uNever;
layout(std430, binding = 0) writeonly buffer Sink {
    float sink[];
};

void main() {
    float x = float(gl_GlobalInvocationID.x) * 1e-6;
    for (uint i = 0u; i < uIterations; ++i) {
        x = x * 0.999 + 0.001;
    }
    if (x == uNever) {
        sink[gl_LocalInvocationIndex] = x;
    }
}
