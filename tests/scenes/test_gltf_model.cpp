// The glTF loader: the sample models load with the counts and bounds their own JSON and buffers give (read
// here independently), and every malformed file -- the collected samples and cases written here -- is a
// ModelError with the right issue code, never a crash.

#include "scenes/orbit/GltfModel.h"

#include "io/TestData.h"

#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace photopic::orbit {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path badDir() {
    return test::testInputDir() / "gltf-bad";
}

std::vector<std::uint8_t> readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t u32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;
}

/// The issue a load fails with; the message must name the file. Fails the test when the load succeeds.
ModelIssue issueOf(const fs::path& file, std::string* message = nullptr, const ModelLimits& limits = {}) {
    try {
        (void)loadModel(file, limits);
    } catch (const ModelError& e) {
        EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << e.what();
        if (message) {
            *message = e.what();
        }
        return e.issue();
    }
    ADD_FAILURE() << file << " loaded";
    return ModelIssue::Unreadable;
}

void expectUnitNormalsAndIndicesInRange(const Model& model) {
    for (const MeshInstance& mesh : model.meshes) {
        for (const Primitive& p : mesh.primitives) {
            ASSERT_EQ(p.indices.size() % 3, 0u);
            for (std::uint32_t i : p.indices) {
                ASSERT_LT(i, p.vertices.size());
            }
            for (const Vertex& v : p.vertices) {
                ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
            }
            ASSERT_GE(p.material, 0);
            ASSERT_LT(std::size_t(p.material), model.materials.size());
        }
    }
}

TEST(GltfModel, TwoCylinderEngineMatchesItsOwnJsonAndBuffer) {
    const fs::path file = test::dataDir() / "gltf" / "2CylinderEngine.glb";
    const Model model = loadModel(file);

    // The expected figures, from the GLB's own chunks: the node tree's world matrices (this file uses
    // matrices only), each index accessor's count, and every POSITION read and transformed here.
    const std::vector<std::uint8_t> glb = readBytes(file);
    const std::uint32_t jsonLength = u32(glb, 12);
    const json gltf = json::parse(glb.begin() + 20, glb.begin() + 20 + jsonLength);
    const std::uint8_t* bin = glb.data() + 20 + jsonLength + 8;
    std::vector<glm::mat4> world(gltf["nodes"].size(), glm::mat4(1.0f));
    std::vector<int> order = gltf["scenes"][0]["nodes"].get<std::vector<int>>();
    std::size_t instances = 0, primitives = 0, triangles = 0;
    Bounds bounds;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const json& node = gltf["nodes"][std::size_t(order[k])];
        ASSERT_FALSE(node.contains("translation") || node.contains("rotation") || node.contains("scale"));
        if (node.contains("matrix")) {
            world[std::size_t(order[k])] *= glm::make_mat4(node["matrix"].get<std::vector<float>>().data());
        }
        for (int child : node.value("children", std::vector<int>{})) {
            world[std::size_t(child)] = world[std::size_t(order[k])];
            order.push_back(child);
        }
        if (!node.contains("mesh")) {
            continue;
        }
        ++instances;
        for (const json& p : gltf["meshes"][node["mesh"].get<std::size_t>()]["primitives"]) {
            ++primitives;
            ASSERT_EQ(p.value("mode", 4), 4);
            triangles += gltf["accessors"][p["indices"].get<std::size_t>()]["count"].get<std::size_t>() / 3;
            const json& a = gltf["accessors"][p["attributes"]["POSITION"].get<std::size_t>()];
            const json& view = gltf["bufferViews"][a["bufferView"].get<std::size_t>()];
            const std::size_t stride = view.value("byteStride", 12);
            const std::size_t start = view.value("byteOffset", 0) + a.value("byteOffset", 0);
            for (std::size_t i = 0; i < a["count"].get<std::size_t>(); ++i) {
                glm::vec3 p3;
                std::memcpy(&p3, bin + start + i * stride, 12);
                bounds.add(glm::vec3(world[std::size_t(order[k])] * glm::vec4(p3, 1.0f)));
            }
        }
    }
    EXPECT_EQ(model.meshes.size(), instances);
    EXPECT_EQ(instances, 67u);
    EXPECT_EQ(model.primitiveCount(), primitives);
    EXPECT_EQ(model.triangleCount(), triangles);
    EXPECT_EQ(model.materials.size(), gltf["materials"].size());
    EXPECT_TRUE(model.images.empty());
    for (int c = 0; c < 3; ++c) {
        const float tolerance = 1e-5f * (bounds.max[c] - bounds.min[c]);
        EXPECT_NEAR(model.bounds.min[c], bounds.min[c], tolerance);
        EXPECT_NEAR(model.bounds.max[c], bounds.max[c], tolerance);
    }
    expectUnitNormalsAndIndicesInRange(model);
}

TEST(GltfModel, BoxTexturedHasAnSrgbBaseColourAtThePngsSize) {
    const fs::path dir = test::dataDir() / "gltf" / "BoxTextured";
    const Model model = loadModel(dir / "BoxTextured.gltf");
    EXPECT_EQ(model.triangleCount(), 12u);
    ASSERT_EQ(model.materials.size(), 1u);
    const int texture = model.materials[0].baseColorTexture;
    ASSERT_GE(texture, 0);
    ASSERT_TRUE(model.textures.at(std::size_t(texture)).srgb);
    const TextureImage& image = model.images.at(std::size_t(model.textures[std::size_t(texture)].image));
    // The PNG's IHDR holds its size big-endian at bytes 16 and 20.
    const std::vector<std::uint8_t> png = readBytes(dir / "CesiumLogoFlat.png");
    const auto bigEndian = [&](std::size_t o) {
        return int(png[o]) << 24 | int(png[o + 1]) << 16 | int(png[o + 2]) << 8 | int(png[o + 3]);
    };
    EXPECT_EQ(image.width, bigEndian(16));
    EXPECT_EQ(image.height, bigEndian(20));
    EXPECT_EQ(image.rgba.size(), std::size_t(image.width) * std::size_t(image.height) * 4);
    for (const MeshInstance& mesh : model.meshes) {
        for (const Primitive& p : mesh.primitives) {
            EXPECT_TRUE(p.hasTexCoords);
        }
    }
    expectUnitNormalsAndIndicesInRange(model);
}

TEST(GltfModel, AMissingOrOversizedImageIsRejected) {
    const fs::path source = test::dataDir() / "gltf" / "BoxTextured";
    EXPECT_EQ(issueOf(source / "BoxTextured.gltf", nullptr, {.maxImageSide = 100}), ModelIssue::TooLarge);
    EXPECT_EQ(issueOf(source / "BoxTextured.gltf", nullptr, {.maxBytes = 100000}), ModelIssue::TooLarge);
    const fs::path dir = fs::temp_directory_path() / "photopic-gltf-missing-image";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(source / "BoxTextured.gltf", dir / "BoxTextured.gltf");
    fs::copy_file(source / "BoxTextured0.bin", dir / "BoxTextured0.bin");
    std::string message;
    EXPECT_EQ(issueOf(dir / "BoxTextured.gltf", &message), ModelIssue::MissingFile);
    EXPECT_NE(message.find("images[0].uri"), std::string::npos) << message;
    fs::remove_all(dir);
}

struct BadSample {
    const char* file;
    ModelIssue issue;
    const char* word; ///< a word the message must hold
};

void PrintTo(const BadSample& sample, std::ostream* os) {
    *os << sample.file;
}

class GltfBadSample : public testing::TestWithParam<BadSample> {};

TEST_P(GltfBadSample, IsRejectedWithItsIssue) {
    std::string message;
    EXPECT_EQ(issueOf(badDir() / GetParam().file, &message), GetParam().issue)
        << modelIssueName(GetParam().issue) << ": " << message;
    EXPECT_NE(message.find(GetParam().word), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Samples, GltfBadSample,
    testing::Values(BadSample{"IndexOutOfRange.gltf", ModelIssue::BadIndex, "index"},
                    BadSample{"BoxWithInfinites.glb", ModelIssue::NonFinite, "finite"},
                    BadSample{"MissingBin.gltf", ModelIssue::MissingFile, "not found"},
                    BadSample{"RecursiveNodes.gltf", ModelIssue::BadNodeGraph, "ancestor"},
                    BadSample{"wrongTypes/badNumber.gltf", ModelIssue::WrongType, "expected"},
                    BadSample{"wrongTypes/badArray.gltf", ModelIssue::WrongType, "expected"}));

/// One triangle (positions, then 16-bit indices) in a .gltf and a .bin written to a fresh folder, for the
/// tests to break one field at a time.
class GltfHostile : public testing::Test {
protected:
    void SetUp() override {
        mDir =
            fs::temp_directory_path() /
            ("photopic-gltf-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
        mGltf = json::parse(R"({
            "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
            "bufferViews": [{"buffer": 0, "byteLength": 36},
                            {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
            "buffers": [{"uri": "tri.bin", "byteLength": 44}]})");
    }
    void TearDown() override { fs::remove_all(mDir); }

    /// Appends floats after the triangle (from byte 44) behind a new buffer view; returns the view's index.
    int addFloats(const std::vector<float>& values) {
        const std::size_t offset = 44 + mExtra.size() * 4;
        mExtra.insert(mExtra.end(), values.begin(), values.end());
        mGltf["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * 4}});
        mGltf["buffers"][0]["byteLength"] = 44 + mExtra.size() * 4;
        return int(mGltf["bufferViews"].size()) - 1;
    }

    fs::path write() const {
        std::vector<std::uint8_t> bin(44 + mExtra.size() * 4, 0);
        std::memcpy(bin.data(), mPositions.data(), 36);
        const std::uint16_t indices[3] = {0, 1, 2};
        std::memcpy(bin.data() + 36, indices, 6);
        if (!mExtra.empty()) {
            std::memcpy(bin.data() + 44, mExtra.data(), mExtra.size() * 4);
        }
        std::ofstream(mDir / "tri.bin", std::ios::binary)
            .write(reinterpret_cast<const char*>(bin.data()), std::streamsize(bin.size()));
        std::ofstream(mDir / "model.gltf") << mGltf.dump();
        return mDir / "model.gltf";
    }

    fs::path mDir;
    json mGltf;
    std::vector<float> mPositions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<float> mExtra;
};

TEST_F(GltfHostile, TheUnbrokenTriangleLoadsWithAFlatNormal) {
    const Model model = loadModel(write());
    ASSERT_EQ(model.triangleCount(), 1u);
    const Primitive& p = model.meshes.at(0).primitives.at(0);
    EXPECT_TRUE(p.flatNormals);
    EXPECT_FLOAT_EQ(p.vertices.at(0).normal.z, 1.0f); // counter-clockwise in the xy plane faces +z
    EXPECT_EQ(model.materials.size(), 1u);            // the default material
    EXPECT_FLOAT_EQ(model.bounds.max.x, 1.0f);
}

TEST_F(GltfHostile, AMirroringNodeKeepsFrontFacesCounterClockwise) {
    mGltf["nodes"][0]["scale"] = {-1, 1, 1};
    const Model model = loadModel(write());
    const Primitive& p = model.meshes.at(0).primitives.at(0);
    EXPECT_FLOAT_EQ(p.vertices.at(0).normal.z, 1.0f);
    EXPECT_FLOAT_EQ(p.vertices.at(p.indices[1]).position.x, 0.0f); // the second and third corners swapped
}

TEST_F(GltfHostile, NormalsAndTangentsFollowAMirroringNode) {
    // Normals near 1e-20 underflow when squared: they must still come out unit length.
    const int normals = addFloats({0, 0, 1e-20f, 0, 0, 1e-20f, 0, 0, 1e-20f});
    const int tangents = addFloats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1});
    mGltf["accessors"].push_back(
        {{"bufferView", normals}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    mGltf["accessors"].push_back(
        {{"bufferView", tangents}, {"componentType", 5126}, {"count", 3}, {"type", "VEC4"}});
    mGltf["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    mGltf["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = 3;
    mGltf["nodes"][0]["scale"] = {-1, 1, 1};
    const Model model = loadModel(write());
    const Primitive& p = model.meshes.at(0).primitives.at(0);
    EXPECT_FALSE(p.flatNormals);
    EXPECT_TRUE(p.hasTangents);
    for (const Vertex& v : p.vertices) {
        EXPECT_FLOAT_EQ(v.normal.z, 1.0f);
        EXPECT_FLOAT_EQ(v.tangent.x, -1.0f);
        EXPECT_FLOAT_EQ(v.tangent.w, -1.0f); // the bitangent flips with the mirror
    }
}

TEST_F(GltfHostile, StripsAndFansAreTriangulated) {
    mPositions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mGltf["meshes"][0]["primitives"][0]["mode"] = 5;
    EXPECT_EQ(loadModel(write()).triangleCount(), 1u);
    mGltf["meshes"][0]["primitives"][0]["mode"] = 6;
    EXPECT_EQ(loadModel(write()).triangleCount(), 1u);
    mGltf["meshes"][0]["primitives"][0]["mode"] = 1;
    EXPECT_EQ(issueOf(write()), ModelIssue::Unsupported);
}

TEST_F(GltfHostile, CountTimesStrideOverflowingIsOutOfBounds) {
    mGltf["accessors"][0]["count"] = std::uint64_t(1) << 62;
    mGltf["bufferViews"][0]["byteStride"] = 12;
    EXPECT_EQ(issueOf(write()), ModelIssue::OutOfBounds);
}

TEST_F(GltfHostile, ByteOffsetsPastTheBufferAreOutOfBounds) {
    mGltf["bufferViews"][0]["byteOffset"] = 40; // the view itself
    EXPECT_EQ(issueOf(write()), ModelIssue::OutOfBounds);
    mGltf["bufferViews"][0]["byteOffset"] = 0;
    mGltf["accessors"][0]["byteOffset"] = 4; // the accessor within its view
    EXPECT_EQ(issueOf(write()), ModelIssue::OutOfBounds);
    mGltf["accessors"][0]["byteOffset"] = std::numeric_limits<std::uint64_t>::max() - 8;
    EXPECT_EQ(issueOf(write()), ModelIssue::OutOfBounds);
}

TEST_F(GltfHostile, NodeCyclesAndSharedChildrenAreBadGraphs) {
    mGltf["nodes"] = json::parse(R"([{"mesh": 0}, {"children": [2]}, {"children": [1]}])");
    std::string message;
    EXPECT_EQ(issueOf(write(), &message), ModelIssue::BadNodeGraph);
    EXPECT_NE(message.find("ancestor"), std::string::npos) << message;
    mGltf["nodes"] = json::parse(R"([{"children": [2]}, {"children": [2]}, {"mesh": 0}])");
    EXPECT_EQ(issueOf(write(), &message), ModelIssue::BadNodeGraph);
    EXPECT_NE(message.find("parent"), std::string::npos) << message;
}

TEST_F(GltfHostile, NanInAPositionIsNonFinite) {
    mPositions[4] = std::numeric_limits<float>::quiet_NaN();
    std::string message;
    EXPECT_EQ(issueOf(write(), &message), ModelIssue::NonFinite);
    EXPECT_NE(message.find("accessors[0]"), std::string::npos) << message;
}

TEST_F(GltfHostile, AccessorsOfTheWrongTypeForTheirUse) {
    mGltf["accessors"][0]["type"] = "VEC2";
    EXPECT_EQ(issueOf(write()), ModelIssue::BadAccessor);
    mGltf["accessors"][0]["type"] = "VEC3";
    mGltf["accessors"][0]["componentType"] = 5123;
    EXPECT_EQ(issueOf(write()), ModelIssue::BadAccessor);
}

TEST_F(GltfHostile, IndicesOutOfRange) {
    mGltf["scene"] = 3;
    EXPECT_EQ(issueOf(write()), ModelIssue::BadIndex);
    mGltf["scene"] = 0;
    mGltf["meshes"][0]["primitives"][0]["material"] = 0;
    mGltf["materials"] = json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    mGltf["textures"] = json::parse(R"([{"source": 5}])");
    std::string message;
    EXPECT_EQ(issueOf(write(), &message), ModelIssue::BadIndex);
    EXPECT_NE(message.find("textures[0].source"), std::string::npos) << message;
}

TEST_F(GltfHostile, NoMeshIsNoGeometry) {
    mGltf["nodes"][0].erase("mesh");
    EXPECT_EQ(issueOf(write()), ModelIssue::NoGeometry);
}

TEST_F(GltfHostile, LimitsAreEnforced) {
    EXPECT_EQ(issueOf(write(), nullptr, {.maxVertices = 2}), ModelIssue::TooLarge);
    EXPECT_EQ(issueOf(write(), nullptr, {.maxFileBytes = 64}), ModelIssue::TooLarge);
    mGltf["extras"] = json::parse(std::string(100, '[') + std::string(100, ']'));
    EXPECT_EQ(issueOf(write()), ModelIssue::ParseError);
}

TEST_F(GltfHostile, AnImageViewPastItsBufferIsCaughtBeforeTinygltfReadsIt) {
    mGltf["images"] = json::parse(R"([{"bufferView": 2, "mimeType": "image/png"}])");
    mGltf["bufferViews"].push_back(json::parse(R"({"buffer": 0, "byteOffset": 40, "byteLength": 4000})"));
    EXPECT_EQ(issueOf(write()), ModelIssue::OutOfBounds);
}

TEST_F(GltfHostile, EveryFileAModelNamesLiesInsideItsFolder) {
    // A file beside the model's folder, which no spelling of a uri may reach.
    write();
    const fs::path outside = mDir.parent_path() / (mDir.filename().string() + "-outside.bin");
    fs::copy_file(mDir / "tri.bin", outside, fs::copy_options::overwrite_existing);
    fs::create_directories(mDir / "sub");
    fs::create_symlink(outside, mDir / "link.bin");
    const std::string name = outside.filename().string();
    for (const std::string& uri : {"../" + name, "..%2F" + name, "..%2f" + name, "sub/../../" + name,
                                   "sub%2F..%2F..%2F" + name, "./../" + name, std::string("link.bin")}) {
        mGltf["buffers"][0]["uri"] = uri;
        std::string message;
        EXPECT_EQ(issueOf(write(), &message), ModelIssue::Unsupported) << uri;
        EXPECT_NE(message.find("outside the model's folder"), std::string::npos) << message;
    }
    // Inside, however it is spelled, loads; so does a link to a file inside.
    fs::create_symlink(mDir / "tri.bin", mDir / "sub" / "inside.bin");
    for (const std::string uri : {"tri.bin", "./tri.bin", "sub/../tri.bin", "sub/inside.bin"}) {
        mGltf["buffers"][0]["uri"] = uri;
        EXPECT_NO_THROW((void)loadModel(write())) << uri;
    }
    // An image's uri goes through the same resolver.
    mGltf["buffers"][0]["uri"] = "tri.bin";
    mGltf["meshes"][0]["primitives"][0]["material"] = 0;
    mGltf["materials"] = json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    mGltf["textures"] = json::parse(R"([{"source": 0}])");
    mGltf["images"] = json::array({{{"uri", "..%2F" + name}}});
    std::string message;
    (void)issueOf(write(), &message);
    EXPECT_NE(message.find("outside the model's folder"), std::string::npos) << message;
    fs::remove(outside);
}

/// A PNG's signature and IHDR, then an IDAT of `idatBytes` zeros: what a header check sees of a real file.
std::vector<std::uint8_t> pngOfSize(std::uint32_t width, std::uint32_t height, std::uint8_t bitDepth,
                                    std::uint8_t colourType, std::size_t idatBytes) {
    std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const auto be32 = [&](std::uint32_t v) {
        for (int shift = 24; shift >= 0; shift -= 8) {
            out.push_back(std::uint8_t(v >> shift));
        }
    };
    const auto chunk = [&](const char* kind, const std::vector<std::uint8_t>& data) {
        be32(std::uint32_t(data.size()));
        out.insert(out.end(), kind, kind + 4);
        out.insert(out.end(), data.begin(), data.end());
        be32(0); // stb_image does not check CRCs
    };
    std::vector<std::uint8_t> ihdr;
    for (const std::uint32_t v : {width, height}) {
        for (int shift = 24; shift >= 0; shift -= 8) {
            ihdr.push_back(std::uint8_t(v >> shift));
        }
    }
    ihdr.insert(ihdr.end(), {bitDepth, colourType, 0, 0, 0});
    chunk("IHDR", ihdr);
    chunk("IDAT", std::vector<std::uint8_t>(idatBytes, 0));
    chunk("IEND", {});
    return out;
}

TEST_F(GltfHostile, TextureBombsAreRefusedFromTheHeader) {
    mGltf["meshes"][0]["primitives"][0]["material"] = 0;
    mGltf["materials"] = json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    mGltf["textures"] = json::parse(R"([{"source": 0}])");
    mGltf["images"] = json::parse(R"([{"uri": "tex.png"}])");
    const auto writePng = [&](const std::vector<std::uint8_t>& png) {
        std::ofstream(mDir / "tex.png", std::ios::binary)
            .write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    };
    // 16384 x 16384 at 1 bit fits in 33 KB of deflate and would decode to 1 GiB of RGBA.
    writePng(pngOfSize(16384, 16384, 1, 0, 40000));
    std::string message;
    EXPECT_EQ(issueOf(write(), &message), ModelIssue::TooLarge);
    EXPECT_NE(message.find("over the limit of 67108864 pixels"), std::string::npos) << message;
    // A header that claims more than its bytes can hold, under every size limit.
    writePng(pngOfSize(4096, 4096, 8, 2, 100));
    EXPECT_EQ(issueOf(write(), &message), ModelIssue::BadImage);
    EXPECT_NE(message.find("cannot hold the 4096 x 4096 image"), std::string::npos) << message;
    EXPECT_EQ(issueOf(write(), &message, {.maxImagePixels = 1000}), ModelIssue::TooLarge);
}

TEST_F(GltfHostile, ExternalReferencesStayRelative) {
    mGltf["buffers"][0]["uri"] = "/etc/passwd";
    EXPECT_EQ(issueOf(write()), ModelIssue::Unsupported);
    mGltf["buffers"][0]["uri"] = "tri.bin";
    const std::string s = mGltf.dump();
    try {
        (void)loadModelFromMemory({reinterpret_cast<const std::uint8_t*>(s.data()), s.size()}, "memory.gltf",
                                  {});
        ADD_FAILURE() << "a model in memory read a file";
    } catch (const ModelError& e) {
        EXPECT_EQ(e.issue(), ModelIssue::MissingFile) << e.what();
    }
}

} // namespace

} // namespace photopic::orbit
