#pragma once
// Named values: a top-level "values" object defines them ({"roughness": 0.2, "tint": [0.8, 0.1, 0.1]}), and
// {"$value": "roughness"} anywhere else in the scene stands for one (docs/scene-authoring.md). No key of the scene
// format starts with '$', so the reference cannot be mistaken for scene content.
#include "renderer/params/json_document.h"

namespace isotrace {

class MemoryBudget;

// Replaces every reference by a copy of the value it names and removes "values" from the document. The copies keep
// the location of the definition (where the value is written) and are charged to `memory`. Throws InputError at a
// reference to an unknown name (with a suggestion) and for a malformed "values" or reference.
void substitute_named_values(JsonValue& document, MemoryBudget& memory);

}  // namespace isotrace
