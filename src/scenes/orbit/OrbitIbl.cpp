#include "scenes/orbit/OrbitIbl.h"

#include "core/Log.h"
#include "gl/ReadbackRing.h"
#include "io/DataPath.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>

namespace photopic::orbit {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

void requireRange(bool ok, const char* option, double value, const char* range) {
    if (!ok) {
        throw std::invalid_argument(
            fmt::format("ibl option {} = {} is out of range {}", option, value, range));
    }
}

void validate(const IblOptions& o) {
    const bool pow2 = o.faceSize > 0 && (o.faceSize & (o.faceSize - 1)) == 0;
    requireRange(pow2 && o.faceSize >= 16 && o.faceSize <= 2048, "faceSize", o.faceSize,
                 "(a power of two in [16, 2048])");
    const int maxLevels = int(std::log2(double(o.faceSize))) + 1;
    requireRange(o.specularLevels >= 2 && o.specularLevels <= maxLevels, "specularLevels", o.specularLevels,
                 "[2, log2(faceSize) + 1]");
    requireRange(o.prefilterSamples >= 1 && o.prefilterSamples <= 4096, "prefilterSamples",
                 o.prefilterSamples, "[1, 4096]");
    requireRange(o.lodBias >= 0.0f && o.lodBias <= 4.0f, "lodBias", o.lodBias, "[0, 4]");
    requireRange(o.lutSize >= 4 && o.lutSize <= 512, "lutSize", o.lutSize, "[4, 512]");
    requireRange(o.lutSamples >= 16 && o.lutSamples <= 65536, "lutSamples", o.lutSamples, "[16, 65536]");
}

GlObject<detail::TextureDeleter> makeCube(int faceSize, int levels, const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
    GlObject<detail::TextureDeleter> cube(id);
    glTextureStorage2D(id, levels, GL_RGBA16F, faceSize, faceSize);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glObjectLabel(GL_TEXTURE, id, -1, name);
    return cube;
}

void dispatchFaces(int faceSize) {
    const GLuint groups = GLuint((faceSize + kPixelGroupSize - 1) / kPixelGroupSize);
    glDispatchCompute(groups, groups, 6);
}

/// Non-finite and negative texels would spread through every filter; they count as black.
ImageF sanitized(const ImageF& image) {
    ImageF out = image;
    for (float& v : out.rgba) {
        v = std::isfinite(v) ? std::max(v, 0.0f) : 0.0f;
    }
    return out;
}

} // namespace

ShaderDefines iblShaderDefines(ShaderDefines extra) {
    extra.emplace_back("ORBIT_IBL_SPECULAR_BINDING", std::to_string(kIblSpecularUnit));
    extra.emplace_back("ORBIT_IBL_LUT_BINDING", std::to_string(kIblLutUnit));
    extra.emplace_back("ORBIT_IBL_BLOCK_BINDING", std::to_string(kIblBlockBinding));
    return extra;
}

namespace {

/// The environment as a mip-mapped texture, wrapping around in longitude, for the cube projection.
Texture equirectSource(const ImageF& env) {
    const int equirectLevels = int(std::floor(std::log2(double(std::max(env.width, env.height))))) + 1;
    Texture source({.extent = {env.width, env.height},
                    .format = GL_RGBA32F,
                    .levels = equirectLevels,
                    .minFilter = GL_LINEAR_MIPMAP_LINEAR,
                    .magFilter = GL_LINEAR,
                    .wrap = GL_CLAMP_TO_EDGE,
                    .debugName = "ibl equirect"});
    glTextureParameteri(source.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    source.uploadRgba32f(env.rgba.data());
    glGenerateTextureMipmap(source.id());
    return source;
}

/// Equirect -> level 0 of `cube` (`face` texels a side), then its mip chain for filtered importance sampling.
void projectToCube(const Texture& source, int sourceWidth, GLuint cube, int face) {
    const Program program = makeComputeProgram("scenes/orbit/orbit_ibl_cube.comp.glsl", iblShaderDefines());
    program.use();
    // 2 x 2 samples per cube texel at the face centre's spacing ((pi / 2) / face / 2 radians) against the
    // equirect's 2 pi / width: the level where the two match.
    const float lod = std::max(0.0f, std::log2(float(sourceWidth) / (8.0f * float(face))));
    setUniform(program, "uFaceSize", face);
    setUniform(program, "uLod", lod);
    glBindTextureUnit(0, source.id());
    glBindImageTexture(0, cube, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    dispatchFaces(face);
    imageWriteBarrier();
    glGenerateTextureMipmap(cube);
}

/// Levels 1 and up of `specular`: the environment cube (`envLevels` levels) prefiltered for a roughness
/// rising to 1 at the last level.
void prefilterSpecular(GLuint environment, int envLevels, GLuint specular, const IblOptions& options) {
    const int face = options.faceSize;
    const Program prefilter =
        makeComputeProgram("scenes/orbit/orbit_ibl_prefilter.comp.glsl", iblShaderDefines());
    prefilter.use();
    glBindTextureUnit(0, environment);
    setUniform(prefilter, "uSampleCount", options.prefilterSamples);
    setUniform(prefilter, "uSourceTexelSolidAngle", cubemapTexelSolidAngle(face));
    setUniform(prefilter, "uLodBias", options.lodBias);
    setUniform(prefilter, "uSourceMaxLod", float(envLevels - 1));
    for (int level = 1; level < options.specularLevels; ++level) {
        const int size = std::max(1, face >> level);
        setUniform(prefilter, "uFaceSize", size);
        setUniform(prefilter, "uRoughness", float(level) / float(options.specularLevels - 1));
        glBindImageTexture(0, specular, level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchFaces(size);
    }
    imageWriteBarrier();
}

/// The split-sum table with the diffuse Fresnel weight, (A, B, W) into `cpuLut` and (A, B, W, 0) returned
/// for the upload; row y = 0 (the smoothest) is the texture's bottom.
std::vector<float> splitSumTable(const IblOptions& options, std::vector<glm::vec3>& cpuLut) {
    const SplitSumLut table = splitSumLut(options.lutSize, options.lutSamples);
    std::vector<float> weights(std::size_t(options.lutSize));
    for (int x = 0; x < options.lutSize; ++x) {
        weights[std::size_t(x)] =
            diffuseSchlickWeight((float(x) + 0.5f) / float(options.lutSize), options.lutSamples);
    }
    cpuLut.resize(std::size_t(options.lutSize) * std::size_t(options.lutSize));
    std::vector<float> rgba(cpuLut.size() * 4);
    for (int y = 0; y < options.lutSize; ++y) {
        for (int x = 0; x < options.lutSize; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(options.lutSize) + std::size_t(x);
            const glm::vec2 ab = table.at(x, y);
            cpuLut[i] = glm::vec3(ab, weights[std::size_t(x)]);
            rgba[i * 4 + 0] = ab.x;
            rgba[i * 4 + 1] = ab.y;
            rgba[i * 4 + 2] = weights[std::size_t(x)];
            rgba[i * 4 + 3] = 0.0f;
        }
    }
    return rgba;
}

Texture uploadSplitSumTable(int size, const std::vector<float>& rgba) {
    Texture lut({.extent = {size, size},
                 .format = GL_RGBA16F,
                 .levels = 1,
                 .minFilter = GL_LINEAR,
                 .magFilter = GL_LINEAR,
                 .wrap = GL_CLAMP_TO_EDGE,
                 .debugName = "ibl split-sum table"});
    glTextureSubImage2D(lut.id(), 0, 0, 0, size, size, GL_RGBA, GL_FLOAT, rgba.data());
    return lut;
}

} // namespace

Ibl::Ibl(const ImageF& equirect, const IblOptions& options)
    : mOptions(options) {
    if (equirect.empty()) {
        throw std::invalid_argument("ibl: the environment image is empty");
    }
    validate(options);
    const auto start = std::chrono::steady_clock::now();
    DebugGroup group("ibl build");
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    const ImageF env = sanitized(equirect);

    // Irradiance: nine coefficients of the radiance, convolved with the clamped cosine over pi, so the shader
    // evaluates the reflected radiance of a white Lambertian surface directly.
    mSh = projectEquirectSh9(env);
    constexpr float kBand[9] = {1.0f,  2.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f, 0.25f,
                                0.25f, 0.25f,       0.25f,       0.25f};
    for (std::size_t i = 0; i < 9; ++i) {
        mParameters.sh[i] = glm::vec4(mSh.c[i] * kBand[i], 0.0f);
    }
    mParameters.specularMaxLevel = float(options.specularLevels - 1);

    const Texture source = equirectSource(env);
    const int face = options.faceSize;
    const int envLevels = int(std::log2(double(face))) + 1;
    mEnvironment = makeCube(face, envLevels, "ibl environment cube");
    mSpecular = makeCube(face, options.specularLevels, "ibl specular cube");
    projectToCube(source, env.width, mEnvironment.id(), face);
    // Level 0 of the specular cube is the mirror: the environment itself.
    glCopyImageSubData(mEnvironment.id(), GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, mSpecular.id(),
                       GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, face, face, 6);
    prefilterSpecular(mEnvironment.id(), envLevels, mSpecular.id(), options);
    glUseProgram(0);
    glBindTextureUnit(0, 0);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);

    mLut = uploadSplitSumTable(options.lutSize, splitSumTable(options, mCpuLut));
    mBlock = ParameterBlock<GpuIblParameters>("ibl parameters", mParameters);
    glFinish();
    mBuildMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    logInfo(
        "ibl: built from a {}x{} environment in {:.0f} ms (cube {}, {} specular levels x {} samples, table "
        "{} x {} samples)",
        env.width, env.height, mBuildMilliseconds, face, options.specularLevels, options.prefilterSamples,
        options.lutSize, options.lutSamples);
}

void Ibl::setIntensity(float intensity) {
    if (!(std::isfinite(intensity) && intensity >= 0.0f)) {
        warnOnce("ibl.intensity",
                 fmt::format("ibl intensity {} is not a finite value >= 0; using 0", intensity));
        intensity = 0.0f;
    }
    mParameters.intensity = intensity;
    mBlock.update(mParameters);
}

void Ibl::bind() const noexcept {
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glBindTextureUnit(kIblSpecularUnit, mSpecular.id());
    glBindTextureUnit(kIblLutUnit, mLut.id());
    mBlock.bind(kIblBlockBinding);
}

IblStandIn::IblStandIn()
    : mCube(makeCube(1, 1, "ibl stand-in cube (no environment)"))
    , mLut({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "ibl stand-in table (no environment)"})
    , mBlock("ibl stand-in parameters (no environment)", GpuIblParameters{.intensity = 0.0f}) {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(mCube.id(), 0, GL_RGBA, GL_FLOAT, zero);
    glClearTexImage(mLut.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

void IblStandIn::bind() const noexcept {
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glBindTextureUnit(kIblSpecularUnit, mCube.id());
    glBindTextureUnit(kIblLutUnit, mLut.id());
    mBlock.bind(kIblBlockBinding);
}

ImageF Ibl::proceduralSky(int width, int height) {
    ImageF sky(std::max(width, 2), std::max(height, 1), 1.0f);
    const glm::vec3 sun = glm::normalize(glm::vec3(0.5f, 0.55f, -0.67f));
    const float sunCos = std::cos(1.5f * kPi / 180.0f);
    for (int y = 0; y < sky.height; ++y) {
        for (int x = 0; x < sky.width; ++x) {
            const glm::vec3 d = equirectDirection(
                {(float(x) + 0.5f) / float(sky.width), (float(y) + 0.5f) / float(sky.height)});
            glm::vec3 c;
            if (d.y >= 0.0f) {
                const float t = std::sqrt(d.y);
                c = glm::mix(glm::vec3(1.0f, 0.95f, 0.85f), glm::vec3(0.25f, 0.45f, 1.0f), t);
            } else {
                c = glm::vec3(0.12f, 0.1f, 0.08f);
            }
            if (glm::dot(d, sun) >= sunCos) {
                c += glm::vec3(400.0f, 380.0f, 340.0f);
            }
            float* p = sky.at(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
        }
    }
    return sky;
}

std::filesystem::path Ibl::defaultEnvironmentPath() {
    try {
        return findDataDir() / "blender_sunrise.exr";
    } catch (const std::exception&) {
        return {};
    }
}

ImageF Ibl::loadEnvironmentOrFallback(const std::filesystem::path& path) {
    std::string problem;
    if (path.empty()) {
        problem = "no environment file was given and no data folder was found";
    } else {
        try {
            ImageF image = readImage(path);
            if (!image.empty()) {
                return image;
            }
            problem = "the image is empty";
        } catch (const std::exception& e) {
            problem = e.what();
        }
    }
    logWarning("ibl: cannot use the environment '{}' ({}); lighting with the procedural sky instead",
               path.string(), problem);
    return proceduralSky();
}

std::vector<glm::vec3> iblProbe(const Ibl& ibl, std::span<const GpuIblProbeQuery> queries) {
    if (queries.empty()) {
        return {};
    }
    const Program program = makeComputeProgram("scenes/orbit/orbit_ibl_probe.comp.glsl", iblShaderDefines());
    const Buffer in(
        {.size = queries.size_bytes(), .flags = 0, .data = queries.data(), .debugName = "ibl probe in"});
    // GPU-only storage, read through a copy into a mapped read-back buffer: reading a buffer the GPU wrote
    // with glGetNamedBufferSubData makes a driver move it to host memory (NVIDIA says so in a performance
    // warning).
    const std::size_t bytes = queries.size() * sizeof(glm::vec4);
    const Buffer out({.size = bytes, .flags = 0, .data = nullptr, .debugName = "ibl probe out"});
    ReadbackRing readback(bytes, 1, "ibl probe");
    program.use();
    glUniform1ui(glGetUniformLocation(program.id(), "uCount"), GLuint(queries.size()));
    ibl.bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint((queries.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    readback.enqueue(out, 0, 0);
    std::vector<glm::vec4> rgba(queries.size());
    for (const ReadbackRing::Result& r : readback.drain()) {
        std::memcpy(rgba.data(), r.bytes.data(), bytes);
    }
    std::vector<glm::vec3> rgb(rgba.size());
    std::transform(rgba.begin(), rgba.end(), rgb.begin(), [](glm::vec4 v) { return glm::vec3(v); });
    return rgb;
}

} // namespace photopic::orbit
