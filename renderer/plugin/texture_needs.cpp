#include "renderer/plugin/texture.h"

namespace isotrace {

TextureNeeds& TextureNeeds::operator|=(const TextureNeeds& other) {
    // The first node that needs anything names where; later ones add what they need.
    if (!uv && !field && (other.uv || other.field)) {
        where = other.where;
        field_path = other.field_path;
    }
    uv = uv || other.uv;
    field = field || other.field;
    return *this;
}

}  // namespace isotrace
