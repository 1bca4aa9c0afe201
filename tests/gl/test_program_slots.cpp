// A program's samplers and images by name (Program::sampler/image, the units its GLSL's layout(binding = N)
// gave), the audit's check that a dispatch found every one of them bound (GlCallAudit.h), and the check that
// a texture bound to an image slot has the format the image's declaration names.

#include "GlCallAudit.h"
#include "GlTest.h"

#include "gl/ShaderLibrary.h"

#include <algorithm>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

constexpr const char* kTwoSamplers = R"(#version 450 core
layout(local_size_x = 1) in;
layout(binding = 3) uniform sampler2D uFirst;
layout(binding = 5) uniform sampler2D uSecond;
layout(binding = 7) uniform sampler2D uUnused; // never read: optimised away
layout(binding = 2, rgba8) writeonly uniform image2D uOutput;
void main() {
    imageStore(uOutput, ivec2(0), texelFetch(uFirst, ivec2(0), 0) + texelFetch(uSecond, ivec2(0), 0));
}
)";

bool mentions(const std::vector<std::string>& problems, std::string_view a, std::string_view b) {
    return std::any_of(problems.begin(), problems.end(), [&](const std::string& p) {
        return p.find(a) != std::string::npos && p.find(b) != std::string::npos;
    });
}

std::string listed(const std::vector<std::string>& problems) {
    std::string all;
    for (const std::string& p : problems) {
        all += "\n  " + p;
    }
    return all;
}

struct Fixture {
    Program program = makeComputeProgramFromSource(kTwoSamplers, "slots probe");
    SamplerSlot first = program.sampler("uFirst");
    SamplerSlot second = program.sampler("uSecond");
    ImageSlot output = program.image("uOutput");
    Texture input{{.extent = {1, 1}, .format = GL_RGBA8, .debugName = "slots probe input"}};
    Texture target{{.extent = {1, 1}, .format = GL_RGBA8, .debugName = "slots probe target"}};
};

// Images declared with a format qualifier, with a define's value, with a define for the unit, and in two
// branches of the preprocessor.
constexpr const char* kImages = R"(#version 450 core
#define MOTION_FORMAT rg32f
#define IDS_UNIT 3
#ifdef NEVER
#define OUT_FORMAT rgba16
#else
#define OUT_FORMAT rgba8
#endif
layout(local_size_x = 1) in;
layout(binding = 1, rgba16f) uniform readonly image2D uColour;
layout(binding = 2, MOTION_FORMAT) uniform readonly image2D uMotion;
layout(binding = IDS_UNIT, r8ui) uniform readonly uimage2D uIds;
#ifdef NEVER
layout(binding = 0, rgba32f) uniform writeonly image2D uOut;
#else
layout(binding = 0, OUT_FORMAT) uniform writeonly image2D uOut;
#endif
void main() {
    imageStore(uOut, ivec2(0), imageLoad(uColour, ivec2(0)) + vec4(imageLoad(uMotion, ivec2(0)).rg,
                                                                   float(imageLoad(uIds, ivec2(0)).r), 0.0));
}
)";

} // namespace

TEST_F(GlTest, ImageSlotsCarryTheFormatTheirDeclarationNames) {
    const Program program = makeComputeProgramFromSource(kImages, "image formats probe");
    EXPECT_EQ(program.image("uColour").format, GLenum(GL_RGBA16F));
    EXPECT_EQ(program.image("uMotion").format, GLenum(GL_RG32F)) << "the define's value";
    EXPECT_EQ(program.image("uIds").format, GLenum(GL_R8UI)) << "the unit a define, the format a qualifier";
    EXPECT_EQ(program.image("uIds").unit, 3);
    EXPECT_EQ(program.image("uOut").format, 0u) << "branches that declare different formats: not checked";
}

TEST_F(GlTest, GlCallAuditReportsAnImageBoundInAnotherFormatThanDeclared) {
    const Program program = makeComputeProgramFromSource(kImages, "image formats probe");
    const ImageSlot colour = program.image("uColour");
    const ImageSlot motion = program.image("uMotion");
    const Texture half{{.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "formats probe rgba16f"}};
    const Texture bytes{{.extent = {1, 1}, .format = GL_RGBA8, .debugName = "formats probe rgba8"}};
    const Texture motion32{{.extent = {1, 1}, .format = GL_RG32F, .debugName = "formats probe rg32f"}};
    GlCallAudit audit;
    bind(colour, half, ImageAccess::Read);
    bind(motion, motion32, ImageAccess::Read);
    EXPECT_TRUE(audit.problems().empty()) << listed(audit.problems());
    bind(colour, bytes, ImageAccess::Read);
    EXPECT_TRUE(mentions(audit.problems(), "image formats probe",
                         "image uColour (unit 1) is declared rgba16f, "
                         "bound to a RGBA8 texture"))
        << listed(audit.problems());
    bind(motion, half, ImageAccess::Read);
    EXPECT_TRUE(mentions(audit.problems(), "", "image uMotion (unit 2) is declared rg32f"))
        << listed(audit.problems());
    EXPECT_EQ(audit.problems().size(), 2u) << listed(audit.problems());
    glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(2, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
}

TEST_F(GlTest, ProgramSlotsCarryTheUnitsTheGlslNames) {
    const Fixture f;
    EXPECT_EQ(f.first.unit, 3);
    EXPECT_EQ(f.second.unit, 5);
    EXPECT_EQ(f.output.unit, 2);
    EXPECT_FALSE(f.program.sampler("uUnused").active()) << "optimised away: a slot that binds nothing";
    try {
        (void)f.program.sampler("uMisspelt");
        ADD_FAILURE() << "a name the program does not declare must throw";
    } catch (const GlError& e) {
        EXPECT_NE(std::string(e.what()).find("slots probe"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("uMisspelt"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)f.program.image("uFirst"), GlError) << "a sampler is not an image";
}

TEST_F(GlTest, GlCallAuditFailsADispatchWithADeclaredSamplerUnbound) {
    const Fixture f;
    f.program.use();
    bind(f.first, f.input);
    bind(f.second, f.input);
    bind(f.output, f.target, ImageAccess::Write);
    dispatch(f.program, Groups{}, Barrier::ImageWrite); // uSecond's binding is now the last dispatch's
    {
        GlCallAudit audit;
        bind(f.first, f.input); // uSecond forgotten
        bind(f.output, f.target, ImageAccess::Write);
        dispatch(f.program, Groups{}, Barrier::ImageWrite);
        EXPECT_TRUE(mentions(audit.problems(), "slots probe", "sampler uSecond (unit 5)"))
            << listed(audit.problems());
        EXPECT_FALSE(mentions(audit.problems(), "", "uFirst")) << listed(audit.problems());
        EXPECT_FALSE(mentions(audit.problems(), "", "uOutput")) << listed(audit.problems());
    }
    {
        GlCallAudit audit;
        bind(f.first, f.input);
        bind(f.second, f.input);
        bind(f.output, f.target, ImageAccess::Write);
        dispatch(f.program, Groups{}, Barrier::ImageWrite);
        EXPECT_TRUE(audit.problems().empty()) << listed(audit.problems());
        dispatch(f.program, Groups{}, Barrier::ImageWrite); // nothing bound since the last dispatch
        EXPECT_TRUE(mentions(audit.problems(), "", "image uOutput (unit 2)")) << listed(audit.problems());
    }
    glUseProgram(0);
}

} // namespace photopic::test
