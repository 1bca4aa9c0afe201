#pragma once
// `photopic info`: the GL context, the colour path the device allows and the quality tier's path.

#include "Command.h"
#include "Commands.h"

namespace photopic::cli {

class InfoCommand final : public Command {
public:
    explicit InfoCommand(CLI::App& parent);
    int run() override;

private:
    bool mForceLdr = false;
    SettingsSources mSettings;
};

} // namespace photopic::cli
