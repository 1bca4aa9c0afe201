#pragma once
// A `photopic` subcommand: it registers its CLI11 subcommand and options on the program's app when it is
// made, holds what they parse into, and run() does the work. Each command is its own class and file
// (InfoCommand, ImageCommand, SettingsCommand, SceneCommand, DemoCommand, BenchCommand, MeterCommand,
// ExposeCommand, FarmCommand); main.cpp makes them, parses and runs the one named.

#include <CLI/CLI.hpp>

namespace photopic::cli {

class Command {
public:
    virtual ~Command() = default;
    Command(const Command&) = delete;
    Command& operator=(const Command&) = delete;

    /// The subcommand, for the options every command shares (-q, --gl-debug).
    [[nodiscard]] CLI::App& app() const { return *mApp; }
    /// Whether the command line named this command.
    [[nodiscard]] bool chosen() const { return mApp->parsed(); }
    /// Whether the command makes a GL context, and so takes --gl-debug.
    [[nodiscard]] virtual bool usesGl() const { return true; }
    /// Does the work; returns the exit code (ExitCode) or throws the errors main() turns into one.
    virtual int run() = 0;

protected:
    explicit Command(CLI::App* app)
        : mApp(app) {}

private:
    CLI::App* mApp;
};

} // namespace photopic::cli
