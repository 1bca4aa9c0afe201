#pragma once
// Runs a list of passes in order. From the passes' declared reads and writes alone it decides, each frame:
// - which passes can run: enabled by their settings and with every required input present (an input is
//   present when the host bound it or an earlier pass that can run writes it);
// - which of those must run: a pass runs when a later running pass or the stage's output reads what it
//   writes, or when it has side effects (readbacks a host polls); the rest are not run at all;
// - which are skipped: enabled and needed but missing a required input. Each is reported in the status and
//   logged once; it never crashes and is never silently a no-op.
// Each running pass gets a debug group, and a memory barrier before it reads anything an earlier pass wrote
// with image or buffer stores.

#include "passes/FramePass.h"

#include <bitset>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace photopic {

/// A pass that was needed this frame but could not run.
struct SkippedPass {
    std::string pass;                 ///< its name
    std::vector<std::string> missing; ///< the required inputs it lacked
};

/// What a stage must produce: every resource listed, or (firstAvailable) the first of them that the stage's
/// passes can produce (a scene debug view's image, else the display image).
struct StageOutputs {
    std::span<const Resource> resources;
    bool firstAvailable = false;
};

class Sequencer {
public:
    using ResourceSet = std::bitset<kResourceCount>;

    /// Plans and runs `passes` against `resources`. Returns the output the stage produced (for
    /// firstAvailable, the chosen one; else the first listed), or Resource::Count when none could be.
    Resource run(std::span<FramePass* const> passes, StageOutputs outputs, FrameContext& ctx,
                 FrameResources& resources);
    /// Plans `passes` as run() would for a frame whose bound resources are `bound`, and runs nothing: the
    /// queries below then answer for this plan. Returns what the stage makes available: `bound` and what
    /// the passes that can run write.
    ResourceSet plan(std::span<FramePass* const> passes, StageOutputs outputs, const FrameContext& ctx,
                     ResourceSet bound);

    /// Names of the passes that ran in the last run() (for tests and timings).
    [[nodiscard]] std::vector<std::string> ranPasses() const;
    /// The passes the last run() had to skip.
    [[nodiscard]] std::vector<SkippedPass> skippedPasses() const;
    [[nodiscard]] bool ran(const FramePass& pass) const;
    /// What the passes the last run() needed read, required or optional: those that ran, and those skipped
    /// for want of a required input whose output a later pass or the stage's output reads.
    [[nodiscard]] ResourceSet neededReads() const;

private:
    /// Skipped: enabled, a required input missing, and a later pass or the stage's output reads what it
    /// writes. SkippedUnread: the same but nothing reads what it writes (reported all the same).
    enum class State : std::uint8_t { Off, Candidate, Blocked, Run, Skipped, SkippedUnread };
    /// The pass's state in the last run() (Off when it was not in the list).
    [[nodiscard]] State stateOf(const FramePass& pass) const;
    ResourceSet plan(std::span<FramePass* const> passes, StageOutputs outputs, const FrameContext& ctx,
                     ResourceSet bound, Resource& output);
    /// plan()'s steps over mPasses: forward, which enabled passes have their inputs (returns what is then
    /// available); the stage's output among `available` (returns it as the first needed resource); backward,
    /// which passes something needed depends on.
    ResourceSet markRunnable(const FrameContext& ctx, ResourceSet bound);
    static ResourceSet chooseOutput(StageOutputs outputs, ResourceSet available, Resource& output);
    void markNeeded(ResourceSet needed);
    void barrierBefore(const FramePass& pass, const FrameResources& resources);

    std::vector<FramePass*> mPasses; ///< the last run's list (capacity kept: no allocation per frame)
    std::vector<State> mStates;
    std::vector<ResourceSet> mMissing;
    ResourceSet mDirty; ///< written since the last barrier
};

} // namespace photopic
