#pragma once
// Which OpenColorIO config isotrace loads when the user names none.
#include <string>

namespace isotrace {

// $OCIO if set and non-empty (the convention every OCIO application follows); otherwise the config
// in the source tree when it exists (running from a build directory); otherwise the installed one.
std::string default_ocio_config_path();

}  // namespace isotrace
