#include "geometry/mesh/ply_loader.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "geometry/mesh/fan_triangulation.h"
#include "geometry/mesh/file_contents.h"
#include "geometry/mesh/mesh_index_problem.h"
#include "geometry/mesh/ply_header.h"
#include "geometry/mesh/ply_value_reader.h"
#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

constexpr std::array<std::string_view, 3> position_names{"x", "y", "z"};
constexpr std::array<std::string_view, 3> normal_names{"nx", "ny", "nz"};
constexpr std::array<std::array<std::string_view, 2>, 4> uv_name_spellings{
    {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}};

// One record's values: scalars by property position, and the items of the one list the caller wants.
struct PlyRecord {
    std::vector<double> scalars;
    std::vector<std::int64_t> list;
};

// Reads record `index` of `element`. The list at `wanted_list` (or none, if -1) is kept; other lists are
// read and dropped, since their length is only known from the data.
void read_record(PlyValueReader& reader, const PlyElement& element, std::uint64_t index, int wanted_list,
                 PlyRecord& record) {
    reader.begin_record(element.name, index);
    record.scalars.resize(element.properties.size());
    record.list.clear();
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!property.is_list) {
            record.scalars[p] = reader.read(property.type, property.name);
            continue;
        }
        const std::int64_t count = reader.read_integer(property.count_type, property.name);
        if (count < 0) reader.fail("negative item count " + std::to_string(count) + " in list '" + property.name + "'");
        for (std::int64_t i = 0; i < count; ++i) {
            if (int(p) == wanted_list) {
                record.list.push_back(reader.read_integer(property.type, property.name));
            } else {
                reader.read(property.type, property.name);
            }
        }
    }
    reader.end_record();
}

// Every record takes at least one byte, so this bounds a reservation against absurd counts in the header.
std::size_t reservable(const PlyElement& element, const PlyValueReader& reader) {
    return std::size_t(std::min<std::uint64_t>(element.count, reader.remaining_bytes()));
}

class PlyMeshReader {
public:
    PlyMeshReader(const std::string& path, std::string_view contents)
        : path_(path), header_(parse_ply_header(contents, path)), reader_(make_ply_value_reader(header_, contents, path)) {}

    TriangleMeshData read() {
        for (const PlyElement& element : header_.elements) {
            if (element.name == "vertex") {
                read_vertices(element);
            } else if (element.name == "face") {
                read_faces(element);
            } else {
                for (std::uint64_t i = 0; i < element.count; ++i) read_record(*reader_, element, i, -1, record_);
            }
        }
        reader_->expect_end();
        return std::move(mesh_);
    }

private:
    void read_vertices(const PlyElement& element) {
        if (element.count > std::numeric_limits<std::uint32_t>::max()) {
            fail_at(element, "too many vertices for 32-bit indices");
        }
        const std::array<int, 3> position = required_scalars(element, position_names);
        const std::optional<std::array<int, 3>> normal = optional_scalars(element, normal_names);
        const std::optional<std::array<int, 2>> uv = uv_properties(element);

        mesh_.positions.reserve(reservable(element, *reader_));
        for (std::uint64_t i = 0; i < element.count; ++i) {
            read_record(*reader_, element, i, -1, record_);
            const auto at = [this](int p) { return float(record_.scalars[std::size_t(p)]); };
            mesh_.positions.emplace_back(at(position[0]), at(position[1]), at(position[2]));
            if (normal) mesh_.normals.emplace_back(at((*normal)[0]), at((*normal)[1]), at((*normal)[2]));
            if (uv) mesh_.uvs.push_back({at((*uv)[0]), at((*uv)[1])});
        }
    }

    void read_faces(const PlyElement& element) {
        const int indices = element.find_property({"vertex_indices", "vertex_index"});
        if (indices < 0) fail_at(element, "missing list property 'vertex_indices'");
        if (!element.properties[std::size_t(indices)].is_list) fail_at(element, "'vertex_indices' must be a list");
        const std::uint64_t vertex_count = declared_vertex_count();

        mesh_.triangles.reserve(reservable(element, *reader_));
        std::vector<std::uint32_t> polygon;
        for (std::uint64_t i = 0; i < element.count; ++i) {
            read_record(*reader_, element, i, indices, record_);
            polygon.clear();
            for (const std::int64_t index : record_.list) {
                if (index < 0 || std::uint64_t(index) >= vertex_count) {
                    reader_->fail(index_out_of_range_problem("vertex", index, vertex_count));
                }
                polygon.push_back(std::uint32_t(index));
            }
            append_fan_triangles(polygon, mesh_.triangles);
        }
    }

    // From the header, because faces may come before vertices.
    std::uint64_t declared_vertex_count() const {
        for (const PlyElement& element : header_.elements) {
            if (element.name == "vertex") return element.count;
        }
        return 0;
    }

    template <std::size_t N>
    std::optional<std::array<int, N>> optional_scalars(const PlyElement& element,
                                                       const std::array<std::string_view, N>& names) const {
        std::array<int, N> positions{};
        std::size_t found = 0;
        for (std::size_t k = 0; k < N; ++k) {
            positions[k] = element.find_property({names[k]});
            if (positions[k] < 0) continue;
            if (element.properties[std::size_t(positions[k])].is_list) {
                fail_at(element, "property '" + std::string(names[k]) + "' must not be a list");
            }
            ++found;
        }
        if (found == 0) return std::nullopt;
        if (found < N) fail_at(element, "needs all or none of " + joined(names));
        return positions;
    }

    template <std::size_t N>
    std::array<int, N> required_scalars(const PlyElement& element, const std::array<std::string_view, N>& names) const {
        for (const std::string_view name : names) {
            if (element.find_property({name}) < 0) fail_at(element, "missing property '" + std::string(name) + "'");
        }
        return *optional_scalars(element, names);
    }

    std::optional<std::array<int, 2>> uv_properties(const PlyElement& element) const {
        for (const auto& names : uv_name_spellings) {
            if (auto uv = optional_scalars(element, names)) return uv;
        }
        return std::nullopt;
    }

    template <std::size_t N>
    static std::string joined(const std::array<std::string_view, N>& names) {
        std::string text;
        for (const std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
        return text;
    }

    [[noreturn]] void fail_at(const PlyElement& element, const std::string& problem) const {
        throw InputError({path_, element.line}, "element " + element.name, problem);
    }

    const std::string& path_;
    const PlyHeader header_;
    const std::unique_ptr<PlyValueReader> reader_;
    PlyRecord record_;
    TriangleMeshData mesh_;
};

}  // namespace

TriangleMeshData load_ply(const std::string& path) {
    const std::string contents = read_file_contents(path);
    TriangleMeshData mesh = PlyMeshReader(path, contents).read();
    mesh.validate(path);
    return mesh;
}

}  // namespace isotrace
