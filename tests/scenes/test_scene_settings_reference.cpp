// Every built-in scene lists its own settings for the settings reference, without a GL context.

#include "scenes/Scene.h"

#include <gtest/gtest.h>

namespace photopic {
namespace {

TEST(SceneSettingsReference, EveryBuiltInSceneDescribesItsSettings) {
    for (const SceneInfo& scene : builtInScenes()) {
        ASSERT_NE(scene.describeSettings, nullptr)
            << scene.name
            << ": its SceneInfo needs describeSceneSettings<ItsSettings> (scenes/SceneRegistry.cpp)";
        const std::vector<SettingDoc> docs = scene.describeSettings(scene.name);
        EXPECT_FALSE(docs.empty()) << scene.name;
        for (const SettingDoc& d : docs) {
            EXPECT_EQ(d.key.rfind(scene.name + ".", 0), 0u) << d.key;
            EXPECT_GE(d.meaning.size(), 8u) << d.key << " has no description in its visit()";
            EXPECT_FALSE(d.defaultJson.empty()) << d.key;
        }
    }
}

TEST(SceneSettingsReference, TestbedRowsMatchItsStruct) {
    for (const SceneInfo& scene : builtInScenes()) {
        if (scene.name != "testbed") {
            continue;
        }
        bool found = false;
        for (const SettingDoc& d : scene.describeSettings(scene.name)) {
            if (d.key == "testbed.fNumber") {
                EXPECT_EQ(d.defaultJson, "2.8");
                EXPECT_EQ(d.allowed, "[0.5, 256]");
                found = true;
            }
        }
        EXPECT_TRUE(found);
        return;
    }
    FAIL() << "no testbed scene";
}

} // namespace
} // namespace photopic
