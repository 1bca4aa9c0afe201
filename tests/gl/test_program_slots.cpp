// A program's samplers and images by name (Program::sampler/image, the units its GLSL's layout(binding = N)
// gave), and the audit's check that a dispatch found every one of them bound (GlCallAudit.h).

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

} // namespace

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
