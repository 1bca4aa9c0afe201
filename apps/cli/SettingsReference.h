#pragma once
// `photopic settings --markdown`: the reference page of every setting (docs/settings.md), built from the
// settings reflection: the post-processing settings, what each preset changes, and every built-in scene's
// own settings.

#include <string>

namespace photopic::cli {

/// The whole page as Markdown. Deterministic: the same build prints the same bytes.
std::string settingsReferenceMarkdown();

} // namespace photopic::cli
