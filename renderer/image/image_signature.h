#pragma once
// Which reader an image file goes to, decided from its first bytes and its extension before OpenImageIO sees it.
// Given content it cannot read with the extension's reader, OpenImageIO tries every reader it has in turn, and
// some of them scan the whole file: 64 MB of zero bytes named z.exr took 20 s to be refused. Here a file is read
// only by the reader of its extension's format, and only when its first bytes are that format's signature.
#include <filesystem>
#include <string>

namespace isotrace {

// OpenImageIO's name of the format ("openexr", "png", "jpeg", ...) that `path`'s extension names. Throws
// InputError naming the file ("cannot read image: ...") when the extension names no format read here or the file's
// first bytes do not match that format's signature. A file that cannot be opened is left to the reader to report
// (the format of its extension is returned).
std::string image_format_of(const std::filesystem::path& path);

}  // namespace isotrace
