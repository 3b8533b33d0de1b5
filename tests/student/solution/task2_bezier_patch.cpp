// The reference solution of task 2 in the student API (BUG_*: one typical mistake).

#include "meshedit/student/student.h"

namespace meshedit::student {
namespace {

Vector3D evaluate_1d(std::vector<Vector3D> points, double t) {
    while (points.size() > 1) {
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            points[i] = (1 - t) * points[i] + t * points[i + 1];
        }
        points.pop_back();
    }
    return points.front();
}

}  // namespace

Vector3D evaluate_patch(const std::vector<std::vector<Vector3D>>& control_points, double u,
                        double v) {
#if defined(BUG_PATCH_UV_SWAPPED)
    std::swap(u, v);
#endif
    std::vector<Vector3D> column;
    for (const std::vector<Vector3D>& row : control_points) {
        column.push_back(evaluate_1d(row, u));
    }
    return evaluate_1d(column, v);
}

}  // namespace meshedit::student
