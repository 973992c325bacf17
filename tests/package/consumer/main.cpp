// Loads a scene through the installed isotrace library, renders it at 16x16 with 1 sample per pixel and
// prints the mean of the beauty RGB channels.
#include <cstdio>
#include <exception>

#include "renderer/core/input_error.h"
#include "renderer/core/version.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <scene.json>\n", argv[0]);
        return 2;
    }
    try {
        isotrace::SceneOverrides overrides;
        overrides.settings.push_back(isotrace::spp_setting(1));
        overrides.settings.push_back(isotrace::resolution_setting(isotrace::RasterSize{16, 16}));
        const std::unique_ptr<isotrace::LoadedScene> scene = isotrace::load_scene(argv[1], overrides);

        isotrace::RenderOptions options;
        options.spp = scene->spp;
        const isotrace::RenderResult result = isotrace::render_scene(*scene, options);
        const isotrace::ImageBuffer image = result.film->resolve();

        const std::size_t channels = image.channels.size();
        if (channels < 3 || image.width != 16 || image.height != 16) {
            std::fprintf(stderr, "unexpected image: %dx%d with %zu channels\n", image.width, image.height, channels);
            return 1;
        }
        double sum = 0;
        for (std::size_t p = 0; p < std::size_t(image.width) * std::size_t(image.height); ++p)
            for (std::size_t c = 0; c < 3; ++c) sum += image.pixels[p * channels + c];
        const double mean = sum / (double(image.width) * image.height * 3);
        std::printf("isotrace %s, OCIO config %s\n", isotrace::kIsotraceVersion,
                    scene->colours->config_path().c_str());
        std::printf("rendered %dx%d at %d spp: mean pixel value %.6g\n", image.width, image.height,
                    result.completed_spp, mean);
        return mean >= 0 ? 0 : 1;
    } catch (const isotrace::InputError& error) {
        std::fprintf(stderr, "input error: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "failure: %s\n", error.what());
        return 1;
    }
}
