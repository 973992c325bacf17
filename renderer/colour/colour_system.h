#pragma once
// ColourSystem: isotrace's single gateway to OpenColorIO. Scene colours and textures are converted
// into the working space on the way in, and rendered images to a display encoding on the way out.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "renderer/colour/default_ocio_config_path.h"
#include "renderer/core/input_error.h"
#include "renderer/math/rgb.h"

namespace isotrace {

class ColourSystem {
public:
    // Loads `config_path` (empty = default_ocio_config_path()). `working_space` may be any colour
    // space name, alias or role of the config. Throws InputError if the config cannot be loaded or
    // the working space is unknown.
    explicit ColourSystem(const std::string& config_path, const std::string& working_space = "ACEScg");
    ~ColourSystem();
    ColourSystem(ColourSystem&&) noexcept;
    ColourSystem& operator=(ColourSystem&&) noexcept;

    const std::string& config_path() const;
    const std::string& working_space() const;  // canonical name, aliases resolved

    bool has_colour_space(const std::string& name) const;  // names, aliases and roles
    std::vector<std::string> colour_space_names() const;   // canonical names only

    // One value from `space` to the working space. `where` and `field` locate the value in the
    // scene file so an unknown space is reported where the user wrote it.
    Rgb to_working(const Rgb& value, const std::string& space, const SourceLocation& where = {},
                   const std::string& field = {}) const;

    // Interleaved RGB (channels = 3) or RGBA (channels = 4, alpha untouched) pixels from `space`
    // to the working space, in place.
    void to_working(float* pixels, std::size_t pixel_count, int channels, const std::string& space) const;

    // Working-space pixels to display-encoded values through a display/view pair, in place.
    // Empty display/view = the config's defaults. Results are not clamped or quantised.
    void to_display(float* pixels, std::size_t pixel_count, int channels, const std::string& display = {},
                    const std::string& view = {}) const;

    std::vector<std::string> displays() const;
    std::string default_display() const;
    std::string default_view(const std::string& display = {}) const;  // empty = default display
    std::vector<std::string> views(const std::string& display = {}) const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace isotrace
