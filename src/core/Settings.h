#pragma once
// Every setting of the pipeline, one typed struct per effect (see core/settings/), gathered here.
// JSON: {"version": 1, "postEffects": {<key>: {...}}} with the keys below.

#include "core/settings/AutoExposureSettings.h"
#include "core/settings/OutputSettings.h"
#include "core/settings/SubjectSettings.h"
#include "core/settings/ToneMappingSettings.h"

namespace photopic {

struct Settings {
    ToneMappingSettings tonemapping;
    OutputSettings output;
    AutoExposureSettings autoExposure;
    SubjectSettings subjects;

    template <class V>
    void visit(V& v) {
        v.object("tonemapping", tonemapping);
        v.object("output", output);
        v.object("autoExposure", autoExposure);
        v.object("subjects", subjects);
    }
};

} // namespace photopic
