#include "renderer/image/image_codec.h"

#include <dlfcn.h>

#include <atomic>
#include <stdexcept>

#include "renderer/core/library_directory.h"
#include "renderer/core/lower_extension.h"
#include "renderer/core/version.h"

#ifndef ISOTRACE_IMAGE_MODULE
#error "the build must define ISOTRACE_IMAGE_MODULE (the image module's file name)"
#endif
#ifndef ISOTRACE_EXR_MODULE
#error "the build must define ISOTRACE_EXR_MODULE (the EXR writer module's file name)"
#endif

namespace isotrace {
namespace {

// What module `module_path`'s entry `entry_name` (of type Entry) returns for this isotrace version (never unloaded).
template <class Entry>
const auto& load_module(const std::filesystem::path& module_path, const char* entry_name, const char* role,
                             const char* purpose) {
    const auto fail = [&](const std::string& reason) {
        return std::runtime_error("cannot load the " + std::string(role) + " " + module_path.string() + ", which " +
                                  purpose + ": " + reason + " (it is built and installed beside libisotrace)");
    };
    // RTLD_LOCAL: the image libraries' symbols stay out of the global namespace.
    void* module = dlopen(module_path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) throw fail(dlerror());
    const auto entry = reinterpret_cast<Entry>(dlsym(module, entry_name));
    if (!entry) throw fail(dlerror());
    const auto* loaded = entry(kIsotraceVersion);
    if (!loaded) throw fail(std::string("it was built for another isotrace version than ") + kIsotraceVersion);
    return *loaded;
}

std::atomic<bool> codec_loaded{false};

const ImageEncoder& exr_encoder() {
    static const ImageEncoder& encoder = load_exr_encoder(library_directory() / ISOTRACE_EXR_MODULE);
    return encoder;
}

}  // namespace

const ImageCodec& load_image_codec(const std::filesystem::path& module_path) {
    return load_module<ImageCodecEntry>(module_path, kImageCodecEntry, "image module",
                                   "reads every image file and writes all but EXR");
}

const ImageEncoder& load_exr_encoder(const std::filesystem::path& module_path) {
    return load_module<ImageEncoderEntry>(module_path, kImageEncoderEntry, "EXR writer module", "writes every EXR file");
}

const ImageCodec& image_codec() {
    static const ImageCodec& codec = load_image_codec(library_directory() / ISOTRACE_IMAGE_MODULE);
    codec_loaded.store(true);
    return codec;
}

bool image_codec_loaded() { return codec_loaded.load(); }

const ImageEncoder& image_encoder_for(const std::filesystem::path& path) {
    return lower_extension(path) == ".exr" ? exr_encoder() : static_cast<const ImageEncoder&>(image_codec());
}

ImageCodecPreload::ImageCodecPreload(std::vector<std::filesystem::path> outputs, std::function<void()> on_failure)
    : thread_([outputs = std::move(outputs), on_failure = std::move(on_failure)] {
          try {
              for (const std::filesystem::path& output : outputs) image_encoder_for(output);
          } catch (const std::exception&) {
              if (on_failure) on_failure();
          }
      }) {}

ImageCodecPreload::~ImageCodecPreload() { thread_.join(); }

}  // namespace isotrace
