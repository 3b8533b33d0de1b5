#pragma once
// Private to meshedit_algorithms: compute_field()'s path for a stored field (fields.h).

#include <vector>

#include "meshedit/core/fields.h"

namespace meshedit {

/// A stored field's values by element index of its site; NaN on deleted elements and
/// everywhere when the mesh no longer has the property.
std::vector<double> stored_field_values(const Mesh& mesh, const FieldInfo& info);

}  // namespace meshedit
