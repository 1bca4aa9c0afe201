// photopic: the command-line front end. Exit codes: 0 ok, 2 bad usage or input, 1 other failure. Each
// command registers its own options (Command.h); here they are made, the line parsed and the one named run.

#include "BenchCommand.h"
#include "Commands.h"
#include "DemoCommand.h"
#include "ImageCommand.h"
#include "InfoCommand.h"
#include "Interrupt.h"
#include "Progress.h"
#include "SceneCommand.h"
#include "SequenceCommands.h"
#include "SettingsCommand.h"

#include "common/Verbosity.h"
#include "core/settings/SettingsJson.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace photopic;
using namespace photopic::cli;

namespace {

/// Every command, in the order `photopic --help` lists them.
std::vector<std::unique_ptr<Command>> makeCommands(CLI::App& app) {
    std::vector<std::unique_ptr<Command>> commands;
    commands.push_back(std::make_unique<InfoCommand>(app));
    commands.push_back(std::make_unique<ImageCommand>(app));
    commands.push_back(std::make_unique<SettingsCommand>(app));
    commands.push_back(std::make_unique<SceneCommand>(app));
    commands.push_back(std::make_unique<DemoCommand>(app));
    commands.push_back(std::make_unique<BenchCommand>(app));
    commands.push_back(std::make_unique<MeterCommand>(app));
    commands.push_back(std::make_unique<ExposeCommand>(app));
    commands.push_back(std::make_unique<FarmCommand>(app));
    return commands;
}

/// The options every command takes: -q, -v and --log-level (the same before or after the command's name),
/// and --gl-debug where a GL context is made.
void addCommonOptions(CLI::App& app, const std::vector<std::unique_ptr<Command>>& commands,
                      Verbosity& verbosity, bool& glDebug) {
    addVerbosityOptions(app, verbosity);
    for (const auto& command : commands) {
        addVerbosityOptions(command->app(), verbosity);
    }
    // A KHR_debug context costs CPU time in every GL call on some drivers: only when asked for.
    const auto addGlDebug = [&glDebug](CLI::App& a) {
        a.add_flag("--gl-debug", glDebug,
                   "a KHR_debug context whose driver messages (errors, performance warnings) reach the log; "
                   "also PHOTOPIC_GL_DEBUG=1");
    };
    addGlDebug(app);
    for (const auto& command : commands) {
        if (command->usesGl()) {
            addGlDebug(command->app());
        }
    }
}

/// Runs the command that was parsed; the errors it throws become exit codes and a line on stderr.
int runChosen(const std::vector<std::unique_ptr<Command>>& commands) {
    try {
        for (const auto& command : commands) {
            if (command->chosen()) {
                return command->run();
            }
        }
        return kFailure;
    } catch (const Interrupted& e) {
        // The outputs were taken back on the way here (RunOutputs), as after any failure.
        std::fprintf(stderr, "photopic: interrupted by %s; the run's outputs were taken back\n",
                     signalName(e.signal));
        return 128 + e.signal;
    } catch (const InputError& e) {
        std::fprintf(stderr, "photopic: %s\n", e.what());
        return kBadInput;
    } catch (const SettingsError& e) {
        std::fprintf(stderr, "photopic: %s", e.what());
        return kBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic: %s\n", e.what());
        return kFailure;
    }
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Photopic: HDR post-processing and eye adaptation on OpenGL 4.5"};
    app.set_version_flag("--version", std::string("photopic ") + PHOTOPIC_VERSION);
    app.require_subcommand(1);
    const std::vector<std::unique_ptr<Command>> commands = makeCommands(app);
    Verbosity verbosity;
    bool glDebug = false;
    addCommonOptions(app, commands, verbosity, glDebug);
    app.footer("Examples:\n"
               "  photopic image in.exr -o out.png --tonemap agx\n"
               "  photopic scene canvas -o out/canvas --motion examples/canvas-motion/tilt.csv\n"
               "  photopic demo -q\n"
               "photopic COMMAND --help: each command's options and examples");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kOk : kBadInput;
    }
    applyVerbosity(verbosity);
    setStatusLines(!verbosity.quiet &&
                   (verbosity.verbose || (verbosity.level != "warning" && verbosity.level != "error")));
    setGlDebug(glDebug);
    Progress::setEnabled(!verbosity.quiet);
    return runChosen(commands);
}
