// The options several commands take (CommandOptions.h).
#include "CommandOptions.h"

#include "core/ShownText.h"
#include "core/ToneCurves.h"
#include "core/settings/SettingsJson.h"

namespace photopic::cli {

const CLI::Validator kOutputPath(
    [](std::string& value) {
        return value.size() > 1 && value.front() == '-'
                   ? "\"" + shownText(value) + "\" looks like an option, not a path (write ./" +
                         shownText(value) + " for a file of that name)"
                   : std::string();
    },
    "PATH");

const std::vector<std::string> kFrameFormats = {"png", "tif", "tiff", "jpg", "jpeg", "exr"};

std::string presetHelp(std::string_view commandDefault) {
    return "look: " + joined(presetNames()) +
           " (stills: photographs, AgX and a tight bloom of what is far past white only; realtime: games and "
           "the built-in scenes, ACES (fitted) and a soft glow over the whole image; neutral: no bloom, "
           "display effects or grading, for measuring). Default: " +
           std::string(commandDefault);
}

void addSettingsOptions(CLI::App* cmd, SettingsSources& s, std::string_view presetDefault) {
    cmd->add_option("--preset", s.preset,
                    presetHelp("the settings file's \"preset\", else " + std::string(presetDefault)) +
                        ". Order: the preset, then the settings file's keys, then "
                        "--tonemap, --exposure, --debug and each --set");
    cmd->add_option("--settings", s.file,
                    "settings JSON file ({\"version\": 1, \"preset\": NAME, \"postEffects\": {...}}, "
                    "every key optional)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--tonemap", s.tonemap,
                    "tone curve: " + joined(toneMapperNames()) + " (same as --set tonemapping.mode=NAME)");
    cmd->add_option("--exposure", s.exposure,
                    "manual exposure in EV (same as --set tonemapping.exposure=EV)");
    cmd->add_option("--debug", s.debugView,
                    "debug view: " + joined(debugViewNames()) +
                        "; views of 3D inputs need them (same as --set debug.view=NAME)");
    cmd->add_option("--set", s.overrides, "override one setting: path=value, e.g. tonemapping.mode=agx")
        ->take_first();
}

void addOcioOptions(CLI::App* cmd, OcioOptions& o) {
    const std::string meaning =
        ": the display image is the OpenColorIO display/view transform of the scene-referred image (after "
        "exposure, bloom and grading, taken as the config's scene_linear role), in place of --tonemap and "
        "the sRGB output; display outputs only (PNG, TIFF, JPEG), and the display-domain effects (FXAA, "
        "SMAA, "
        "grain, vignette, overlays) do not apply to it";
    cmd->add_option("--ocio-display", o.display,
                    "OpenColorIO display (default: the config's default)" + meaning);
    cmd->add_option("--ocio-view", o.view,
                    "OpenColorIO view of the display (default: the display's default)");
    cmd->add_option("--ocio-config", o.config, "OpenColorIO config file (default: $OCIO)");
}

void addMaxPixelsOption(CLI::App* cmd, std::int64_t& maxPixels) {
    cmd->add_option("--max-pixels", maxPixels,
                    "refuse input images with more pixels than this, before decoding them (memory bound)")
        ->check(CLI::Range(std::int64_t(1), std::int64_t(1) << 40))
        ->capture_default_str();
}

void addDisplayEncodingOptions(CLI::App* cmd, std::optional<int>& bitDepth, int& jpegQuality) {
    cmd->add_option("--bit-depth", bitDepth,
                    "bits per channel of the display image and of PNG and TIFF outputs: 8 or 16 (16 renders "
                    "the display passes at 16 bits, output.bitDepth=16; JPEG is 8-bit only); default: the "
                    "settings' output.bitDepth, 8")
        ->check(CLI::IsMember({8, 16}));
    cmd->add_option("--jpeg-quality", jpegQuality, "quality of JPEG outputs, 1 to 100")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
}

void addChannelOptions(CLI::App* cmd, std::string& preset, std::string& layer,
                       std::vector<std::string>& aovs) {
    cmd->add_option(
           "--aovs", preset,
           "the channel names and conventions of a renderer: photopic (R G B A, Z, N.*, motion.*) or "
           "blender (<layer>.Combined, .Depth, .Normal, .Vector, .AO, .IndexOB); default: blender "
           "for files that carry Blender's BlenderMultiChannel attribute, else photopic")
        ->check(CLI::IsMember({"photopic", "blender"}));
    cmd->add_option("--layer", layer,
                    "the layer to read (Blender's view layer, or P of P.R/P.G/P.B); default: the only one, "
                    "or the unprefixed channels; several and none chosen is an error listing them");
    cmd->add_option("--aov", aovs,
                    "KIND=CHANNELS[:CONVENTIONS], repeatable: feed KIND (color, depth, normals, motion, ao, "
                    "objectid) from these channels (full names, names in the layer, or a prefix its "
                    "components complete; 'none' reads none), in these conventions (depth: planar|radial; "
                    "normals: world|world-zup|camera; motion: pixels|ndc|uv, current-minus-previous|"
                    "previous-minus-current|next-minus-current, y-up|y-down, jittered|unjittered, "
                    "pair=1|pair=2), e.g. --aov depth=P.Z:radial --aov motion=:jittered")
        ->take_all()
        ->allow_extra_args(false);
}

void addSequenceInputs(CLI::App* cmd, ImageOptions& o) {
    cmd->add_option("inputs", o.inputs,
                    "input images, or frame-numbered patterns when no such file exists (f%04d.exr, "
                    "f.####.exr, f@.exr), as photopic image takes them")
        ->required();
    auto* frames = cmd->add_option("--frames", o.frames, "frames A-B of a pattern input, inclusive");
    cmd->add_option("--start-number", o.startNumber, "a pattern input's first frame")
        ->check(CLI::NonNegativeNumber)
        ->excludes(frames);
}

} // namespace photopic::cli
