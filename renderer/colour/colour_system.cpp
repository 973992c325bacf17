#include "renderer/colour/colour_system.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "renderer/colour/cpu_processor_cache.h"
#include "renderer/core/did_you_mean.h"

namespace OCIO = OCIO_NAMESPACE;

namespace isotrace {
namespace {

std::string quoted_list(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
    return list;
}

// Problem text for `name`, which is not among `valid`: a suggestion when one is close, otherwise
// every valid choice, so the user never has to open the config to find out what is allowed.
// `what` describes the name, e.g. `view "Filmic"`.
std::string unknown_name_problem(const std::string& what, const std::string& name,
                                 const std::vector<std::string>& valid,
                                 const std::vector<std::string>& spellings) {
    const std::string suggestion = did_you_mean(name, spellings);
    if (!suggestion.empty()) return "unknown " + what + suggestion;
    return "unknown " + what + "; valid choices: " + quoted_list(valid);
}

OCIO::ConstConfigRcPtr load_config(const std::string& path) {
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        // Parsing alone accepts dangling references (a role naming a missing space, say); catch
        // them now rather than at the first conversion halfway through a render.
        config->validate();
        return config;
    } catch (const OCIO::Exception& error) {
        throw InputError(SourceLocation{path}, {},
                         std::string("cannot load OpenColorIO config: ") + error.what());
    }
}

// Wrong channel counts are programming errors in the caller, not user input.
void check_channels(int channels) {
    if (channels != 3 && channels != 4)
        throw std::invalid_argument("colour conversion needs 3 or 4 channels, got " +
                                    std::to_string(channels));
}

// The buffer as one row, which is all OCIO needs for per-pixel transforms.
OCIO::PackedImageDesc as_image(float* pixels, std::size_t pixel_count, int channels) {
    return OCIO::PackedImageDesc(pixels, static_cast<long>(pixel_count), 1, channels);
}

}  // namespace

struct ColourSystem::State {
    std::string config_path;
    OCIO::ConstConfigRcPtr config;
    std::string working_space;
    CpuProcessorCache to_working_processors;  // keyed by (source space, working space)
    CpuProcessorCache to_display_processors;  // keyed by (display, view)

    std::vector<std::string> colour_space_names() const {
        std::vector<std::string> names;
        const int count = config->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
        for (int i = 0; i < count; ++i)
            names.emplace_back(
                config->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i));
        return names;
    }

    // Every spelling the config accepts for a colour space (names, aliases, roles), so suggestions
    // can offer any of them.
    std::vector<std::string> colour_space_spellings() const {
        std::vector<std::string> spellings;
        for (int i = 0; i < config->getNumRoles(); ++i) spellings.emplace_back(config->getRoleName(i));
        for (const std::string& name : colour_space_names()) {
            spellings.push_back(name);
            OCIO::ConstColorSpaceRcPtr space = config->getColorSpace(name.c_str());
            for (std::size_t i = 0; i < space->getNumAliases(); ++i)
                spellings.emplace_back(space->getAlias(i));
        }
        return spellings;
    }

    std::string canonical_space(const std::string& space, const SourceLocation& where,
                                const std::string& field) const {
        if (OCIO::ConstColorSpaceRcPtr found = config->getColorSpace(space.c_str())) return found->getName();
        throw InputError(where, field,
                         unknown_name_problem("colour space \"" + space + "\"", space, colour_space_names(),
                                              colour_space_spellings()));
    }

    std::vector<std::string> displays() const {
        std::vector<std::string> names;
        for (int i = 0; i < config->getNumDisplays(); ++i) names.emplace_back(config->getDisplay(i));
        return names;
    }

    std::string checked_display(const std::string& display) const {
        if (display.empty()) return config->getDefaultDisplay();
        const std::vector<std::string> valid = displays();
        if (std::find(valid.begin(), valid.end(), display) == valid.end())
            throw InputError({}, "display",
                             unknown_name_problem("display \"" + display + "\"", display, valid, valid));
        return display;
    }

    std::vector<std::string> views(const std::string& display) const {
        std::vector<std::string> names;
        for (int i = 0; i < config->getNumViews(display.c_str()); ++i)
            names.emplace_back(config->getView(display.c_str(), i));
        return names;
    }

    std::string checked_view(const std::string& display, const std::string& view) const {
        if (view.empty()) return config->getDefaultView(display.c_str());
        const std::vector<std::string> valid = views(display);
        if (std::find(valid.begin(), valid.end(), view) == valid.end())
            throw InputError({}, "view",
                             unknown_name_problem("view \"" + view + "\" of display \"" + display + "\"",
                                                  view, valid, valid));
        return view;
    }

    // Processor construction only fails when the config itself is broken, so blame the config file.
    template <typename MakeProcessor>
    OCIO::ConstCPUProcessorRcPtr build(const std::string& conversion, MakeProcessor make_processor) const {
        try {
            return make_processor()->getDefaultCPUProcessor();
        } catch (const OCIO::Exception& error) {
            throw InputError(SourceLocation{config_path}, {},
                             "cannot build " + conversion + ": " + error.what());
        }
    }

    OCIO::ConstCPUProcessorRcPtr working_processor(const std::string& canonical_source) const {
        return to_working_processors.get({canonical_source, working_space}, [&] {
            return build("conversion from \"" + canonical_source + "\" to \"" + working_space + "\"", [&] {
                return config->getProcessor(canonical_source.c_str(), working_space.c_str());
            });
        });
    }
};

ColourSystem::ColourSystem(const std::string& config_path, const std::string& working_space)
    : state_(std::make_unique<State>()) {
    state_->config_path = config_path.empty() ? default_ocio_config_path() : config_path;
    try {
        state_->config = load_config(state_->config_path);
    } catch (const InputError& error) {
        const char* from_environment = std::getenv("OCIO");
        if (config_path.empty() && from_environment && state_->config_path == from_environment)
            throw InputError(error.location(), "$OCIO", error.problem());  // say where the path came from
        throw;
    }
    state_->working_space = state_->canonical_space(working_space, {}, "working_space");
    // Rendering sums and scales radiance: that is only right in a scene-linear space. Configs without encodings
    // cannot be checked and are trusted.
    OCIO::ConstColorSpaceRcPtr space = state_->config->getColorSpace(state_->working_space.c_str());
    const std::string encoding = space->getEncoding();
    if (space->isData() || (!encoding.empty() && encoding != "scene-linear"))
        throw InputError({}, "working_space",
                         "the working space must be scene-linear, but \"" + state_->working_space + "\" is " +
                             (space->isData() ? std::string("a data space") : "encoded \"" + encoding + "\"") +
                             "; choose ACEScg, ACES2065-1 or lin_rec709");
}

ColourSystem::~ColourSystem() = default;
ColourSystem::ColourSystem(ColourSystem&&) noexcept = default;
ColourSystem& ColourSystem::operator=(ColourSystem&&) noexcept = default;

const std::string& ColourSystem::config_path() const { return state_->config_path; }

const std::string& ColourSystem::working_space() const { return state_->working_space; }

bool ColourSystem::has_colour_space(const std::string& name) const {
    return state_->config->getColorSpace(name.c_str()) != nullptr;
}

std::vector<std::string> ColourSystem::colour_space_names() const { return state_->colour_space_names(); }

Rgb ColourSystem::to_working(const Rgb& value, const std::string& space, const SourceLocation& where,
                             const std::string& field) const {
    const std::string source = state_->canonical_space(space, where, field);
    float rgb[3] = {value.r, value.g, value.b};
    state_->working_processor(source)->applyRGB(rgb);
    return {rgb[0], rgb[1], rgb[2]};
}

void ColourSystem::to_working(float* pixels, std::size_t pixel_count, int channels,
                              const std::string& space) const {
    check_channels(channels);
    const std::string source = state_->canonical_space(space, {}, {});
    if (pixel_count == 0) return;
    OCIO::PackedImageDesc image = as_image(pixels, pixel_count, channels);
    state_->working_processor(source)->apply(image);
}

void ColourSystem::to_display(float* pixels, std::size_t pixel_count, int channels,
                              const std::string& display, const std::string& view) const {
    check_channels(channels);
    const std::string chosen_display = state_->checked_display(display);
    const std::string chosen_view = state_->checked_view(chosen_display, view);
    if (pixel_count == 0) return;

    const State& state = *state_;
    OCIO::ConstCPUProcessorRcPtr processor =
        state.to_display_processors.get({chosen_display, chosen_view}, [&] {
            return state.build("view \"" + chosen_view + "\" of display \"" + chosen_display + "\"", [&] {
                return state.config->getProcessor(state.working_space.c_str(), chosen_display.c_str(),
                                                  chosen_view.c_str(), OCIO::TRANSFORM_DIR_FORWARD);
            });
        });
    OCIO::PackedImageDesc image = as_image(pixels, pixel_count, channels);
    processor->apply(image);
}

std::vector<std::string> ColourSystem::displays() const { return state_->displays(); }

std::string ColourSystem::default_display() const { return state_->config->getDefaultDisplay(); }

std::string ColourSystem::default_view(const std::string& display) const {
    return state_->config->getDefaultView(state_->checked_display(display).c_str());
}

std::vector<std::string> ColourSystem::views(const std::string& display) const {
    return state_->views(state_->checked_display(display));
}

}  // namespace isotrace
