#pragma once
// Where the loaded libisotrace lives, so that files installed beside it (the OCIO config, the image module) are
// found wherever an installed tree is moved.
#include <filesystem>

namespace isotrace {

// The directory of the libisotrace shared object this process loaded (absolute when the dynamic loader found it
// through an absolute or $ORIGIN path); empty if the loader cannot say.
std::filesystem::path library_directory();

}  // namespace isotrace
