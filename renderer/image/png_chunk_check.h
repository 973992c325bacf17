#pragma once
// A check of a PNG file's chunk lengths before OpenImageIO opens it: every chunk must fit in the bytes the file has
// left. libpng trusts a text chunk's declared length and allocates it before reading: a 764-byte file whose tEXt
// chunk claims 1.95 GB took 2 GB of memory (found by the texture fuzzer), before any pixel could be charged.
#include <filesystem>

namespace isotrace {

// Does nothing for files that do not start with the PNG signature. Throws InputError naming the file, the chunk and
// its claimed length when a chunk runs past the end of the file. Reads only the 8-byte chunk headers.
void check_png_chunk_sizes(const std::filesystem::path& path);

}  // namespace isotrace
