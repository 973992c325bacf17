#pragma once
// Which OpenColorIO config isotrace loads when the user names none.
#include <string>

namespace isotrace {

// $OCIO if set and non-empty (the convention every OCIO application follows); otherwise the config installed
// beside the library (found relative to the loaded libisotrace, so installs are relocatable); otherwise the
// config in the source tree (running from a build directory).
std::string default_ocio_config_path();

}  // namespace isotrace
