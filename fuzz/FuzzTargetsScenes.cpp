// Entry point for the scenes' file readers: the glTF loader, from bytes in memory, alone and with a model
// folder in a sandbox whose files outside that folder are watched.

#include "FuzzTargets.h"

#include "scenes/orbit/GltfModel.h"

#include <glm/geometric.hpp>

#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace photopic::fuzz {

namespace {

namespace fs = std::filesystem;

// Small enough that one input stays fast, large enough for the committed samples to load whole.
constexpr orbit::ModelLimits kModelLimits{.maxVertices = std::uint64_t(1) << 16,
                                          .maxIndices = std::uint64_t(1) << 18,
                                          .maxImageSide = 1024,
                                          .maxBytes = std::uint64_t(64) << 20};

void removeSandbox();

[[noreturn]] void broken(const std::string& promise) {
    std::fprintf(stderr, "fuzz target: promise broken: %s\n", promise.c_str());
    removeSandbox();
    std::abort();
}

/// What a renderer relies on: indices in range, unit normals, finite positions, valid material and texture
/// indices, images of their stated size.
void checkModel(const orbit::Model& model) {
    for (const orbit::MeshInstance& mesh : model.meshes) {
        for (const orbit::Primitive& p : mesh.primitives) {
            if (p.indices.size() % 3 != 0 || p.material < 0 ||
                std::size_t(p.material) >= model.materials.size()) {
                broken("a primitive's index count or material");
            }
            for (std::uint32_t i : p.indices) {
                if (i >= p.vertices.size()) {
                    broken("an index past the vertices");
                }
            }
            for (const orbit::Vertex& v : p.vertices) {
                // Component by component: the length of a finite position far out can overflow.
                const bool finite =
                    std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z);
                if (!finite || std::abs(glm::length(v.normal) - 1.0f) > 1e-3f) {
                    broken("a non-finite position or a normal that is not unit length");
                }
            }
        }
    }
    for (const orbit::ModelTexture& t : model.textures) {
        if (t.image < 0 || std::size_t(t.image) >= model.images.size()) {
            broken("a texture's image index");
        }
    }
    for (const orbit::TextureImage& image : model.images) {
        if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4) {
            broken("an image's size");
        }
    }
}

// ---------------------------------------------------------------------------------------------------------------
// The sandbox: a model folder with files around it that no model in it may read.
//
//   ROOT/secret.bin, ROOT/secret.png        outside the model folder
//   ROOT/model/buffer.bin, texture.png      the model's own files (and sub/buffer.bin)
//   ROOT/model/link.bin -> ../secret.bin    symbolic links out of it (and link.png -> ../secret.png)
//
// The committed seeds name these files (fuzz/corpus/gltf/uri_*.gltf). An inotify watch on ROOT and on /etc
// sees each open or read of a file directly in either, by whichever path it was reached (.., %2F, a
// symbolic link: the kernel reports the file the open ended at), whatever the loader's own code believes.
// The model folder itself is not watched: what is in it is the model's.

/// 64 bytes: a triangle's positions (3 x VEC3 float, bytes 0-35) and texture coordinates (3 x VEC2 float,
/// bytes 36-59), then 4 bytes of padding. The same in every .bin, so a model loads from any of them whole.
std::vector<char> triangleBuffer() {
    const std::array<float, 15> values{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    std::vector<char> bytes(64, 0);
    std::memcpy(bytes.data(), values.data(), sizeof(values));
    return bytes;
}

/// A 2 x 2 RGBA PNG, 8 bits a sample.
constexpr unsigned char kTinyPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d,
    0x24, 0x00, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xf0,
    0x1f, 0x0c, 0x81, 0x34, 0x08, 0x34, 0x00, 0x00, 0x49, 0x49, 0x09, 0x78, 0x9c, 0x51, 0x17, 0x92,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

struct Sandbox {
    fs::path root;
    fs::path model;
    int watch = -1; ///< the inotify descriptor, non-blocking
    int rootWatch = -1;
    int etcWatch = -1;
};

/// Made on the first glTF input and kept to the end of the process; the atexit handler (or broken(), as
/// abort() skips that) removes its folder and frees it.
Sandbox* gSandbox = nullptr;

void removeSandbox() {
    if (gSandbox) {
        std::error_code ec;
        fs::remove_all(gSandbox->root, ec);
        if (gSandbox->watch >= 0)
            close(gSandbox->watch);
        delete gSandbox;
        gSandbox = nullptr;
    }
}

[[noreturn]] void sandboxFailed(const std::string& what) {
    std::fprintf(stderr, "fuzz target: cannot set up the glTF sandbox: %s: %s\n", what.c_str(),
                 std::strerror(errno));
    removeSandbox();
    std::abort();
}

void writeFile(const fs::path& file, const void* bytes, std::size_t size) {
    std::ofstream out(file, std::ios::binary);
    out.write(static_cast<const char*>(bytes), std::streamsize(size));
    out.close();
    if (!out)
        sandboxFailed("cannot write " + file.string());
}

const Sandbox& sandbox() {
    if (gSandbox)
        return *gSandbox;
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern =
        (tmp && *tmp ? std::string(tmp) : std::string("/tmp")) + "/photopic-fuzz-gltf-XXXXXX";
    if (!mkdtemp(pattern.data()))
        sandboxFailed("mkdtemp " + pattern);
    gSandbox = new Sandbox{.root = pattern, .model = fs::path(pattern) / "model"};
    std::atexit(removeSandbox);
    Sandbox& box = *gSandbox;
    std::error_code ec;
    fs::create_directories(box.model / "sub", ec);
    if (ec)
        sandboxFailed("cannot create " + (box.model / "sub").string());
    const std::vector<char> buffer = triangleBuffer();
    for (const fs::path& file :
         {box.root / "secret.bin", box.model / "buffer.bin", box.model / "sub/buffer.bin"})
        writeFile(file, buffer.data(), buffer.size());
    for (const fs::path& file : {box.root / "secret.png", box.model / "texture.png"})
        writeFile(file, kTinyPng, sizeof(kTinyPng));
    fs::create_symlink("../secret.bin", box.model / "link.bin", ec);
    if (!ec)
        fs::create_symlink("../secret.png", box.model / "link.png", ec);
    if (ec)
        sandboxFailed("cannot link out of " + box.model.string());
    // Watched after the files are written, so the writes are not reported.
    box.watch = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (box.watch < 0)
        sandboxFailed("inotify_init1");
    box.rootWatch = inotify_add_watch(box.watch, box.root.c_str(), IN_OPEN | IN_ACCESS);
    box.etcWatch = inotify_add_watch(box.watch, "/etc", IN_OPEN | IN_ACCESS);
    if (box.rootWatch < 0 || box.etcWatch < 0)
        sandboxFailed("inotify_add_watch on " + box.root.string() + " and /etc");
    return box;
}

/// The files outside the model folder opened or read since the last call, each once, by its full path.
struct Accesses {
    std::vector<std::string> sandbox; ///< in ROOT: a folder of this process's own, so only its reads
    std::vector<std::string> etc;     ///< in /etc: any process's
};

bool contains(const std::vector<std::string>& files, const std::string& file) {
    return std::find(files.begin(), files.end(), file) != files.end();
}

Accesses drain(const Sandbox& box) {
    Accesses seen;
    alignas(inotify_event) std::array<char, 16384> buffer;
    for (;;) {
        const ssize_t got = read(box.watch, buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            break; // EAGAIN: nothing more
        for (ssize_t at = 0; at < got;) {
            inotify_event event;
            std::memcpy(&event, buffer.data() + at, sizeof(event));
            const std::string name = event.len ? std::string(buffer.data() + at + sizeof(event)) : "";
            at += ssize_t(sizeof(event) + event.len);
            // Files only: a folder opened is a listing (ROOT/model's own among them), which other programs
            // make too (an indexer walking the temporary folder); what a model must not do is read a file.
            if (event.mask & IN_ISDIR || name.empty() || name == "model")
                continue;
            std::vector<std::string>& files = event.wd == box.rootWatch ? seen.sandbox : seen.etc;
            const std::string file =
                ((event.wd == box.rootWatch ? box.root : fs::path("/etc")) / name).string();
            if (!contains(files, file))
                files.push_back(file);
        }
    }
    return seen;
}

/// Runs `load` and aborts when it read a file outside the model folder.
///
/// A file in ROOT counts at once. A watch on /etc reports every process's reads, and other programs read
/// files there at any moment (each program start reads /etc/ld.so.cache), so a file in /etc counts only
/// when each of four more runs of the load reads it again and none of the quiet waits after them (each as
/// long as its run) sees it: a load that reads the file reads it every time, while a file another program
/// reads often enough to show up in every run shows up in the waits too.
template <typename Load>
void checkNoOutsideAccess(const Sandbox& box, const char* what, const Load& load) {
    const auto run = [&] {
        (void)drain(box);
        const auto start = std::chrono::steady_clock::now();
        load();
        const auto took = std::chrono::steady_clock::now() - start;
        return std::pair(drain(box), took);
    };
    const Accesses seen = run().first;
    std::vector<std::string> etc = seen.etc;
    for (int confirm = 0; confirm < 4 && !etc.empty(); ++confirm) {
        const auto again = run();
        std::this_thread::sleep_for(again.second);
        const std::vector<std::string> quiet = drain(box).etc;
        std::erase_if(etc, [&](const std::string& file) {
            return !contains(again.first.etc, file) || contains(quiet, file);
        });
    }
    std::vector<std::string> outside = seen.sandbox;
    outside.insert(outside.end(), etc.begin(), etc.end());
    if (!outside.empty()) {
        std::string files;
        for (const std::string& file : outside)
            files += (files.empty() ? "" : ", ") + file;
        broken(std::string(what) + " read a file outside the model folder " + box.model.string() + ": " +
               files);
    }
}

void loadAndCheck(const std::uint8_t* data, std::size_t size, const fs::path& name, const fs::path& baseDir) {
    try {
        checkModel(orbit::loadModelFromMemory({data, size}, name, baseDir, kModelLimits));
    } catch (const orbit::ModelError&) {
    }
}

} // namespace

void gltfModel(const std::uint8_t* data, std::size_t size) {
    const Sandbox& box = sandbox();
    // No base folder: a model from memory must be self-contained, so no input reads a file.
    checkNoOutsideAccess(box, "a load with no base folder",
                         [&] { loadAndCheck(data, size, "fuzz.glb", {}); });
    // The sandbox's model folder: the model may read what is in it, nothing around it.
    checkNoOutsideAccess(box, "a load from the sandbox's model folder",
                         [&] { loadAndCheck(data, size, box.model / "fuzz.gltf", box.model); });
}

} // namespace photopic::fuzz
