#include "tools/cli/ply_writer.h"

#include <bit>
#include <sstream>

#include "renderer/core/atomic_file.h"
#include "renderer/core/version.h"

namespace isotrace::cli {

void write_ply(const std::string& path, const TriangleMeshData& mesh) {
    static_assert(std::endian::native == std::endian::little, "binary_little_endian is written as in memory");
    std::ostringstream out(std::ios::binary);
    {
        const bool normals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
        out << "ply\nformat binary_little_endian 1.0\ncomment isotrace " << kIsotraceVersion << "\nelement vertex "
            << mesh.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n";
        if (normals) out << "property float nx\nproperty float ny\nproperty float nz\n";
        out << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            out.write(reinterpret_cast<const char*>(&mesh.positions[i]), sizeof(Vec3f));
            if (normals) out.write(reinterpret_cast<const char*>(&mesh.normals[i]), sizeof(Vec3f));
        }
        const unsigned char three = 3;
        for (const auto& t : mesh.triangles) {
            out.write(reinterpret_cast<const char*>(&three), 1);
            out.write(reinterpret_cast<const char*>(t.data()), sizeof(t));
        }
    }
    write_file_atomically(path, out.str());
}

}  // namespace isotrace::cli
