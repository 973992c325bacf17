#include "renderer/colour/default_ocio_config_path.h"

#include <cstdlib>
#include <filesystem>

#if !defined(ISOTRACE_SOURCE_CONFIG_DIR) || !defined(ISOTRACE_INSTALL_CONFIG_DIR)
#error "the build must define ISOTRACE_SOURCE_CONFIG_DIR and ISOTRACE_INSTALL_CONFIG_DIR"
#endif

namespace isotrace {

std::string default_ocio_config_path() {
    if (const char* from_environment = std::getenv("OCIO"); from_environment && *from_environment)
        return from_environment;

    const std::filesystem::path in_source_tree =
        std::filesystem::path(ISOTRACE_SOURCE_CONFIG_DIR) / "ocio" / "isotrace.ocio";
    std::error_code ignored;  // an unreadable source tree just means "use the installed config"
    if (std::filesystem::is_regular_file(in_source_tree, ignored)) return in_source_tree.string();

    return (std::filesystem::path(ISOTRACE_INSTALL_CONFIG_DIR) / "ocio" / "isotrace.ocio").string();
}

}  // namespace isotrace
