#include "renderer/colour/default_ocio_config_path.h"

#include <cstdlib>
#include <filesystem>

#include "renderer/core/library_directory.h"

#if !defined(ISOTRACE_SOURCE_CONFIG_DIR) || !defined(ISOTRACE_LIBRARY_TO_CONFIG_DIR)
#error "the build must define ISOTRACE_SOURCE_CONFIG_DIR and ISOTRACE_LIBRARY_TO_CONFIG_DIR"
#endif

namespace isotrace {
namespace {

// The config installed beside this library (<prefix>/lib -> <prefix>/share/isotrace/config), found from the
// library's own location so that an installed tree works wherever it is moved.
std::filesystem::path installed_config() {
    const std::filesystem::path library = library_directory();
    if (library.empty()) return {};
    return library / ISOTRACE_LIBRARY_TO_CONFIG_DIR / "ocio" / "isotrace.ocio";
}

}  // namespace

std::string default_ocio_config_path() {
    if (const char* from_environment = std::getenv("OCIO"); from_environment && *from_environment)
        return from_environment;
    std::error_code ignored;  // an unreadable candidate just means "try the next one"
    const std::filesystem::path installed = installed_config();
    if (!installed.empty() && std::filesystem::is_regular_file(installed, ignored))
        return installed.lexically_normal().string();
    return (std::filesystem::path(ISOTRACE_SOURCE_CONFIG_DIR) / "ocio" / "isotrace.ocio").string();
}

}  // namespace isotrace
