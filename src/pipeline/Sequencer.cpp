#include "pipeline/Sequencer.h"

#include "core/Log.h"

#include <fmt/format.h>

namespace photopic {

namespace {

Sequencer::ResourceSet usesOf(const FramePass& pass, Access access) {
    Sequencer::ResourceSet set;
    for (const ResourceUse& u : pass.uses()) {
        if (u.access == access) {
            set.set(std::size_t(u.resource));
        }
    }
    return set;
}

} // namespace

Sequencer::ResourceSet Sequencer::plan(std::span<FramePass* const> passes, StageOutputs outputs,
                                       const FrameContext& ctx, ResourceSet bound) {
    Resource output = Resource::Count;
    return plan(passes, outputs, ctx, bound, output);
}

Sequencer::ResourceSet Sequencer::plan(std::span<FramePass* const> passes, StageOutputs outputs,
                                       const FrameContext& ctx, ResourceSet bound, Resource& output) {
    mPasses.assign(passes.begin(), passes.end());
    mStates.assign(passes.size(), State::Off);
    mMissing.assign(passes.size(), ResourceSet());
    const ResourceSet available = markRunnable(ctx, bound);
    ResourceSet needed = chooseOutput(outputs, available, output);
    markNeeded(needed);
    return available;
}

Sequencer::ResourceSet Sequencer::markRunnable(const FrameContext& ctx, ResourceSet bound) {
    // Forward: what can run, and what will be available.
    ResourceSet available = bound;
    for (std::size_t i = 0; i < mPasses.size(); ++i) {
        const FramePass& pass = *mPasses[i];
        if (!pass.enabled(ctx)) {
            continue;
        }
        const ResourceSet missing = usesOf(pass, Access::Read) & ~available;
        if (missing.any()) {
            mStates[i] = State::Blocked;
            mMissing[i] = missing;
            continue;
        }
        mStates[i] = State::Candidate;
        available |= usesOf(pass, Access::Write);
    }
    return available;
}

Sequencer::ResourceSet Sequencer::chooseOutput(StageOutputs outputs, ResourceSet available,
                                               Resource& output) {
    ResourceSet needed;
    output = Resource::Count;
    for (const Resource r : outputs.resources) {
        if (outputs.firstAvailable) {
            if (available.test(std::size_t(r))) {
                output = r;
                needed.set(std::size_t(r));
                break;
            }
        } else {
            needed.set(std::size_t(r));
            if (output == Resource::Count) {
                output = r;
            }
        }
    }
    if (outputs.firstAvailable && output == Resource::Count && !outputs.resources.empty()) {
        output = outputs.resources.back();
        needed.set(std::size_t(output));
    }
    return needed;
}

void Sequencer::markNeeded(ResourceSet needed) {
    // Backward: what must run. A needed pass that cannot run is skipped and reported; a pass that must run
    // needs what it reads, required or optional.
    for (std::size_t i = mPasses.size(); i-- > 0;) {
        const FramePass& pass = *mPasses[i];
        if (mStates[i] == State::Off) {
            continue;
        }
        const ResourceSet writes = usesOf(pass, Access::Write);
        const bool wanted = pass.hasSideEffects() || (writes & needed).any();
        if (mStates[i] == State::Blocked) {
            // Blocked passes are reported whether or not a consumer ran: the settings asked for them.
            mStates[i] = wanted ? State::Skipped : State::SkippedUnread;
            continue;
        }
        if (!wanted) {
            mStates[i] = State::Off;
            continue;
        }
        mStates[i] = State::Run;
        // What this pass overwrites was not needed from earlier passes unless it also reads it.
        needed &= ~writes;
        needed |= usesOf(pass, Access::Read) | usesOf(pass, Access::ReadOptional);
    }
}

void Sequencer::barrierBefore(const FramePass& pass, const FrameResources& resources) {
    const ResourceSet reads = (usesOf(pass, Access::Read) | usesOf(pass, Access::ReadOptional)) & mDirty;
    if (reads.none()) {
        return;
    }
    GLbitfield bits = 0;
    for (std::size_t r = 0; r < kResourceCount; ++r) {
        if (!reads.test(r)) {
            continue;
        }
        if (resources.buffer(Resource(r)) != nullptr) {
            bits |= GL_SHADER_STORAGE_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                    GL_COMMAND_BARRIER_BIT;
        } else {
            bits |= GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT;
        }
    }
    glMemoryBarrier(bits);
    mDirty.reset();
}

Resource Sequencer::run(std::span<FramePass* const> passes, StageOutputs outputs, FrameContext& ctx,
                        FrameResources& resources) {
    ResourceSet bound;
    for (std::size_t r = 0; r < kResourceCount; ++r) {
        bound.set(r, resources.has(Resource(r)));
    }
    Resource output = Resource::Count;
    plan(passes, outputs, ctx, bound, output);
    mDirty.reset();
    for (std::size_t i = 0; i < passes.size(); ++i) {
        FramePass& pass = *passes[i];
        if (mStates[i] == State::Skipped || mStates[i] == State::SkippedUnread) {
            try {
                std::string missing;
                for (std::size_t r = 0; r < kResourceCount; ++r) {
                    if (mMissing[i].test(r)) {
                        missing +=
                            fmt::format("{}{}", missing.empty() ? "" : ", ", resourceName(Resource(r)));
                    }
                }
                warnOnce(fmt::format("skip.{}.{}", pass.name(), missing),
                         fmt::format("pass '{}' skipped: the frame has no {}", pass.name(), missing));
            } catch (...) { // logging must not take the frame down
            }
            continue;
        }
        if (mStates[i] != State::Run) {
            continue;
        }
        barrierBefore(pass, resources);
        {
            const DebugGroup group(pass.name());
            pass.execute(ctx, resources);
        }
        for (const ResourceUse& u : pass.uses()) {
            if (u.access == Access::Write) {
                mDirty.set(std::size_t(u.resource));
            }
        }
    }
    return output;
}

std::vector<std::string> Sequencer::ranPasses() const {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < mPasses.size(); ++i) {
        if (mStates[i] == State::Run) {
            names.emplace_back(mPasses[i]->name());
        }
    }
    return names;
}

std::vector<SkippedPass> Sequencer::skippedPasses() const {
    std::vector<SkippedPass> skipped;
    for (std::size_t i = 0; i < mPasses.size(); ++i) {
        if (mStates[i] != State::Skipped && mStates[i] != State::SkippedUnread) {
            continue;
        }
        SkippedPass s{.pass = std::string(mPasses[i]->name()), .missing = {}};
        for (std::size_t r = 0; r < kResourceCount; ++r) {
            if (mMissing[i].test(r)) {
                s.missing.emplace_back(resourceName(Resource(r)));
            }
        }
        skipped.push_back(std::move(s));
    }
    return skipped;
}

Sequencer::State Sequencer::stateOf(const FramePass& pass) const {
    for (std::size_t i = 0; i < mPasses.size(); ++i) {
        if (mPasses[i] == &pass) {
            return mStates[i];
        }
    }
    return State::Off;
}

bool Sequencer::ran(const FramePass& pass) const {
    return stateOf(pass) == State::Run;
}

Sequencer::ResourceSet Sequencer::neededReads() const {
    ResourceSet reads;
    for (std::size_t i = 0; i < mPasses.size(); ++i) {
        if (mStates[i] == State::Run || mStates[i] == State::Skipped) {
            reads |= usesOf(*mPasses[i], Access::Read) | usesOf(*mPasses[i], Access::ReadOptional);
        }
    }
    return reads;
}

} // namespace photopic
