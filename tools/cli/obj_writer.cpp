#include "tools/cli/obj_writer.h"

#include <cstdio>
#include <sstream>

#include "renderer/core/atomic_file.h"
#include "renderer/core/version.h"

namespace isotrace::cli {

void write_obj(const std::string& path, const std::vector<NamedMesh>& meshes) {
    std::ostringstream out;
    out << "# isotrace " << kIsotraceVersion << "\n";
    char line[128];
    std::size_t first_vertex = 1, first_normal = 1;  // OBJ indices are 1-based and global across objects
    for (const NamedMesh& named : meshes) {
        const TriangleMeshData& mesh = named.mesh;
        out << "o " << named.name << "\n";
        for (const Vec3f& p : mesh.positions) {
            std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
            out << line;
        }
        for (const Vec3f& n : mesh.normals) {
            std::snprintf(line, sizeof line, "vn %.7g %.7g %.7g\n", double(n.x), double(n.y), double(n.z));
            out << line;
        }
        const bool with_normals = !mesh.normals.empty();
        for (const auto& t : mesh.triangles) {
            const std::size_t a = first_vertex + t[0], b = first_vertex + t[1], c = first_vertex + t[2];
            if (with_normals)
                std::snprintf(line, sizeof line, "f %zu//%zu %zu//%zu %zu//%zu\n", a, first_normal + t[0], b,
                              first_normal + t[1], c, first_normal + t[2]);
            else
                std::snprintf(line, sizeof line, "f %zu %zu %zu\n", a, b, c);
            out << line;
        }
        first_vertex += mesh.positions.size();
        first_normal += mesh.normals.size();
    }
    write_file_atomically(path, out.str());
}

}  // namespace isotrace::cli
