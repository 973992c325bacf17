#include "tools/cli/ply_writer.h"

#include <bit>
#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "renderer/core/atomic_file.h"
#include "renderer/core/version.h"

namespace isotrace::cli {

void write_ply(const std::string& path, const TriangleMeshData& mesh) {
    static_assert(std::endian::native == std::endian::little, "the PLY writer writes the machine's byte order");
    write_atomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        const bool with_normals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
        out << "ply\nformat binary_little_endian 1.0\ncomment isotrace " << kIsotraceVersion << "\nelement vertex "
            << mesh.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n";
        if (with_normals) out << "property float nx\nproperty float ny\nproperty float nz\n";
        out << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            out.write(reinterpret_cast<const char*>(&mesh.positions[i]), 3 * sizeof(float));
            if (with_normals) out.write(reinterpret_cast<const char*>(&mesh.normals[i]), 3 * sizeof(float));
        }
        const std::uint8_t three = 3;
        for (const auto& t : mesh.triangles) {
            out.write(reinterpret_cast<const char*>(&three), 1);
            out.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(std::uint32_t));
        }
        if (!out.flush()) throw std::runtime_error("cannot write " + path);
    });
}

}  // namespace isotrace::cli
