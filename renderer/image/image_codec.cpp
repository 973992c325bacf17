#include "renderer/image/image_codec.h"

#include <dlfcn.h>

#include <stdexcept>

#include "renderer/core/library_directory.h"
#include "renderer/core/version.h"

#ifndef ISOTRACE_IMAGE_MODULE
#error "the build must define ISOTRACE_IMAGE_MODULE (the image module's file name)"
#endif

namespace isotrace {

const ImageCodec& load_image_codec(const std::filesystem::path& module_path) {
    const auto fail = [&](const std::string& reason) {
        return std::runtime_error("cannot load the image module " + module_path.string() +
                                  ", which reads and writes every image file: " + reason +
                                  " (it is built and installed beside libisotrace)");
    };
    // RTLD_LOCAL: OpenImageIO's symbols stay out of the global namespace; the module is never unloaded.
    void* module = dlopen(module_path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) throw fail(dlerror());
    const auto entry = reinterpret_cast<ImageCodecEntry>(dlsym(module, kImageCodecEntry));
    if (!entry) throw fail(dlerror());
    const ImageCodec* codec = entry(kIsotraceVersion);
    if (!codec) throw fail(std::string("it was built for another isotrace version than ") + kIsotraceVersion);
    return *codec;
}

const ImageCodec& image_codec() {
    static const ImageCodec& codec = load_image_codec(library_directory() / ISOTRACE_IMAGE_MODULE);
    return codec;
}

ImageCodecPreload::ImageCodecPreload(std::function<void()> on_failure)
    : thread_([on_failure = std::move(on_failure)] {
          try {
              image_codec();
          } catch (const std::exception&) {
              if (on_failure) on_failure();
          }
      }) {}

ImageCodecPreload::~ImageCodecPreload() { thread_.join(); }

}  // namespace isotrace
