// A renderer of its own with Photopic dropped in: a GLFW window, glad as the GL loader, a small 3D scene
// (spinning boxes on a floor, one of them a light far brighter than white) drawn into HDR colour, view-space
// normals, motion vectors and depth; Photopic gets those by name each frame, jitters the projection for TAA,
// and draws the finished frame into the window's back buffer.
//
//   photopic_glfw_host [--frames N] [--screenshot FILE.ppm] [--size WxH]
//
// With --frames the run is deterministic (fixed 1/60 s steps) and ends after N frames; --screenshot writes
// the last frame as a binary PPM. Exit status 1 when Photopic reported an input error.

#include <glad/gl.h> // the host's loader; Photopic's header is loader-free, so the order does not matter

#include <GLFW/glfw3.h>
#include <photopic/photopic.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

const char* kVertexShader = R"(#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel, uPrevModel, uView, uJitteredViewProj, uViewProj, uPrevViewProj;
out vec3 vWorldNormal;
out vec3 vViewNormal;
out vec4 vClip;
out vec4 vPrevClip;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    gl_Position = uJitteredViewProj * world;
    vClip = uViewProj * world; // unjittered: motion vectors carry no jitter
    vPrevClip = uPrevViewProj * (uPrevModel * vec4(aPosition, 1.0));
    vWorldNormal = mat3(uModel) * aNormal;
    vViewNormal = mat3(uView) * vWorldNormal;
}
)";

const char* kFragmentShader = R"(#version 450 core
in vec3 vWorldNormal;
in vec3 vViewNormal;
in vec4 vClip;
in vec4 vPrevClip;
uniform vec3 uAlbedo, uEmission, uSunDirection, uSunColor, uSkyColor;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec2 oMotion;
void main() {
    vec3 n = normalize(vWorldNormal);
    vec3 light = uSunColor * max(dot(n, uSunDirection), 0.0) + uSkyColor * (0.5 + 0.5 * n.y);
    oColor = vec4(uAlbedo * light + uEmission, 1.0);
    oNormal = vec4(normalize(vViewNormal), 1.0);
    oMotion = (vClip.xy / vClip.w - vPrevClip.xy / vPrevClip.w) * 0.5; // UV space: current minus previous
}
)";

struct Options {
    int frames = 0; // 0: until the window closes
    std::string screenshot;
    int width = 960, height = 540;
};

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--frames" && hasValue) {
            o.frames = std::atoi(argv[++i]);
        } else if (arg == "--screenshot" && hasValue) {
            o.screenshot = argv[++i];
        } else if (arg == "--size" && hasValue && std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) == 2) {
        } else {
            std::fprintf(stderr, "usage: %s [--frames N] [--screenshot FILE.ppm] [--size WxH]\n", argv[0]);
            return false;
        }
    }
    return o.width > 0 && o.height > 0 && o.frames >= 0;
}

GLuint compile(GLenum stage, const char* source) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::array<char, 2048> log{};
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        std::fprintf(stderr, "shader: %s\n", log.data());
    }
    return shader;
}

GLuint makeProgram() {
    const GLuint program = glCreateProgram();
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    return program;
}

/// A unit cube, 36 vertices of position and normal.
GLuint makeCube(GLuint& buffer) {
    std::vector<float> v;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            const glm::vec3 n = axes[axis] * sign;
            const glm::vec3 u = axes[(axis + 1) % 3], w = axes[(axis + 2) % 3];
            const glm::vec3 c[4] = {n - u - w, n + u - w, n + u + w, n - u + w};
            const int order[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; ++k) {
                const glm::vec3 p = 0.5f * c[sign > 0 ? order[k] : order[5 - k]];
                v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
            }
        }
    }
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(v.size() * sizeof(float)), v.data(), 0);
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, buffer, 0, 6 * sizeof(float));
    for (GLuint attribute : {0u, 1u}) {
        glEnableVertexArrayAttrib(vao, attribute);
        glVertexArrayAttribFormat(vao, attribute, 3, GL_FLOAT, GL_FALSE, attribute * 3 * sizeof(float));
        glVertexArrayAttribBinding(vao, attribute, 0);
    }
    return vao;
}

/// The host's G-buffer: HDR colour, view normals, motion and depth.
struct Targets {
    GLuint color = 0, normals = 0, motion = 0, depth = 0, framebuffer = 0;

    Targets(int w, int h) {
        const std::array<std::pair<GLuint*, GLenum>, 4> textures{{{&color, GL_RGBA16F},
                                                                  {&normals, GL_RGBA16F},
                                                                  {&motion, GL_RG16F},
                                                                  {&depth, GL_DEPTH_COMPONENT32F}}};
        for (const auto& [name, format] : textures) {
            glCreateTextures(GL_TEXTURE_2D, 1, name);
            glTextureStorage2D(*name, 1, format, w, h);
        }
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, color, 0);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT1, normals, 0);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT2, motion, 0);
        glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);
        const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        glNamedFramebufferDrawBuffers(framebuffer, 3, buffers);
    }
    ~Targets() {
        glDeleteFramebuffers(1, &framebuffer);
        for (GLuint t : {color, normals, motion, depth}) {
            glDeleteTextures(1, &t);
        }
    }
    Targets(const Targets&) = delete;
    Targets& operator=(const Targets&) = delete;
};

struct Box {
    glm::vec3 position, scale, albedo, emission;
    float spin; // radians per second about y
};

const std::vector<Box> kBoxes = {
    {{0, -0.55f, 0}, {12, 0.1f, 12}, {0.5f, 0.5f, 0.5f}, {0, 0, 0}, 0.0f},    // floor
    {{-1.2f, 0, 0}, {0.8f, 1.0f, 0.8f}, {0.8f, 0.3f, 0.2f}, {0, 0, 0}, 0.6f}, // red
    {{0.4f, 0, -0.8f}, {0.7f, 0.7f, 0.7f}, {0.2f, 0.5f, 0.8f}, {0, 0, 0}, -0.9f},
    {{1.5f, 0.2f, 0.6f}, {0.3f, 0.3f, 0.3f}, {1, 1, 1}, {60, 45, 30}, 1.5f}, // a lamp: far above white
};

glm::mat4 modelOf(const Box& b, float t) {
    return glm::scale(glm::rotate(glm::translate(glm::mat4(1), b.position), b.spin * t, {0, 1, 0}), b.scale);
}

photopic::Matrix4 toArray(const glm::mat4& m) {
    photopic::Matrix4 out;
    std::memcpy(out.data(), glm::value_ptr(m), sizeof(out));
    return out;
}

glm::mat4 toGlm(const photopic::Matrix4& m) {
    return glm::make_mat4(m.data());
}

bool writePpm(const std::string& path, int w, int h) {
    std::vector<unsigned char> rgb(std::size_t(w) * h * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << w << " " << h << "\n255\n";
    for (int y = h - 1; y >= 0; --y) { // GL rows run bottom-up
        out.write(reinterpret_cast<const char*>(&rgb[std::size_t(y) * w * 3]), std::streamsize(w) * 3);
    }
    return bool(out);
}

/// Renders frames until the window closes or `o.frames` have run; returns the exit status.
int run(GLFWwindow* window, const Options& o) {
    photopic::PostProcessor post({.settingsJson = R"({"version": 1, "postEffects": {
        "aa": {"mode": "taa"}, "bloom": {"intensity": 0.05}, "autoExposure": {"enabled": true}}})"});
    GLuint cubeBuffer = 0;
    const GLuint cube = makeCube(cubeBuffer);
    const GLuint program = makeProgram();
    auto uniform = [&](const char* name) { return glGetUniformLocation(program, name); };
    const Targets targets(o.width, o.height);
    const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.8f, 0.3f));

    photopic::HostCamera camera;
    camera.verticalFov = glm::radians(50.0f);
    camera.nearPlane = 0.1f;
    camera.farPlane = 100.0f;
    const glm::mat4 projection = glm::perspective(camera.verticalFov, float(o.width) / float(o.height),
                                                  camera.nearPlane, camera.farPlane);
    camera.projection = toArray(projection);
    glm::mat4 prevViewProj(1.0f);
    std::vector<glm::mat4> prevModels(kBoxes.size());
    int status = 0;
    for (std::uint64_t frame = 0; !glfwWindowShouldClose(window); ++frame) {
        const float dt = 1.0f / 60.0f, t = float(frame) * dt;
        const glm::mat4 view =
            glm::lookAt(glm::vec3(4.5f * std::sin(0.2f * t), 1.8f, 4.5f * std::cos(0.2f * t)),
                        glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
        camera.view = toArray(view);
        camera.prevViewProjection = toArray(frame == 0 ? projection * view : prevViewProj);
        camera.cut = frame == 0;
        const std::array<float, 2> jitter = post.beginFrame(frame, dt, &camera);
        const glm::mat4 jittered =
            toGlm(photopic::PostProcessor::jitteredProjection(camera.projection, jitter, o.width, o.height));

        // The host's own pass, with the host's own state.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.framebuffer);
        glViewport(0, 0, o.width, o.height);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_CULL_FACE);
        const float sky[4] = {0.6f, 0.8f, 1.3f, 1.0f}, zero[4] = {0, 0, 0, 0}, one = 1.0f;
        glClearBufferfv(GL_COLOR, 0, sky);
        glClearBufferfv(GL_COLOR, 1, zero);
        glClearBufferfv(GL_COLOR, 2, zero);
        glClearBufferfv(GL_DEPTH, 0, &one);
        glUseProgram(program);
        glBindVertexArray(cube);
        glUniformMatrix4fv(uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
        glUniformMatrix4fv(uniform("uJitteredViewProj"), 1, GL_FALSE, glm::value_ptr(jittered * view));
        glUniformMatrix4fv(uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(projection * view));
        glUniformMatrix4fv(uniform("uPrevViewProj"), 1, GL_FALSE, camera.prevViewProjection.data());
        glUniform3fv(uniform("uSunDirection"), 1, glm::value_ptr(sun));
        glUniform3f(uniform("uSunColor"), 2.0f, 1.9f, 1.7f);
        glUniform3f(uniform("uSkyColor"), 0.3f, 0.4f, 0.6f);
        for (std::size_t i = 0; i < kBoxes.size(); ++i) {
            const glm::mat4 model = modelOf(kBoxes[i], t);
            glUniformMatrix4fv(uniform("uModel"), 1, GL_FALSE, glm::value_ptr(model));
            glUniformMatrix4fv(uniform("uPrevModel"), 1, GL_FALSE,
                               glm::value_ptr(frame == 0 ? model : prevModels[i]));
            glUniform3fv(uniform("uAlbedo"), 1, glm::value_ptr(kBoxes[i].albedo));
            glUniform3fv(uniform("uEmission"), 1, glm::value_ptr(kBoxes[i].emission));
            glDrawArrays(GL_TRIANGLES, 0, 36);
            prevModels[i] = model;
        }
        prevViewProj = projection * view;

        // Photopic: colour, depth, normals and motion by name; the result into the window's back buffer.
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
        post.execute({.color = targets.color,
                      .depth = targets.depth,
                      .normals = targets.normals,
                      .motion = targets.motion,
                      .camera = &camera,
                      .sunDirection = std::array<float, 3>{sun.x, sun.y, sun.z},
                      .dt = dt,
                      .frameIndex = frame},
                     photopic::FramebufferTarget{.framebuffer = 0, .width = fbWidth, .height = fbHeight});
        for (const std::string& e : post.status().inputErrors) {
            std::fprintf(stderr, "photopic_glfw_host: input error: %s\n", e.c_str());
            status = 1;
        }
        const bool last = o.frames > 0 && frame + 1 >= std::uint64_t(o.frames);
        if (last && !o.screenshot.empty()) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            glReadBuffer(GL_BACK);
            if (!writePpm(o.screenshot, fbWidth, fbHeight)) {
                std::fprintf(stderr, "photopic_glfw_host: cannot write %s\n", o.screenshot.c_str());
                status = 1;
            }
        }
        glfwSwapBuffers(window);
        glfwPollEvents();
        if (last) {
            break;
        }
    }
    const photopic::Status s = post.status();
    std::printf("photopic_glfw_host: %s path, ran:", s.hdrPath ? "HDR" : "LDR");
    for (const std::string& pass : s.ran) {
        std::printf(" [%s]", pass.c_str());
    }
    std::printf("\n");
    glDeleteProgram(program);
    glDeleteVertexArrays(1, &cube);
    glDeleteBuffers(1, &cubeBuffer);
    return status;
}

} // namespace

int main(int argc, char** argv) {
    Options options;
    if (!parse(argc, argv, options)) {
        return 2;
    }
    if (!glfwInit()) {
        std::fprintf(stderr, "photopic_glfw_host: GLFW cannot start (no display?)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    GLFWwindow* window =
        glfwCreateWindow(options.width, options.height, "Photopic in a GLFW host", nullptr, nullptr);
    if (window == nullptr) {
        std::fprintf(stderr, "photopic_glfw_host: no OpenGL 4.5 core window\n");
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(options.frames > 0 ? 0 : 1);
    int status = 1;
    if (gladLoadGL(glfwGetProcAddress) == 0) {
        std::fprintf(stderr, "photopic_glfw_host: glad could not load GL\n");
    } else {
        try {
            status = run(window, options);
        } catch (const photopic::Error& e) {
            std::fprintf(stderr, "photopic_glfw_host: %s\n", e.what());
        }
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}
