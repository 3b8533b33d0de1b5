// The reference solution of task 1 in the student API. A BUG_* definition compiles one
// typical mistake instead (tests/student/CMakeLists.txt builds one library per mistake).

#include "meshedit/student/student.h"

namespace meshedit::student {

std::vector<Vector2D> evaluate_step(const std::vector<Vector2D>& points, double t) {
    std::vector<Vector2D> out;
#if defined(BUG_STEP_ONE_TOO_MANY)
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        out.push_back((1 - t) * points[i] + t * points[i + 1]);
    }
    out.push_back(points.back());  // keeps the last point
#elif defined(BUG_STEP_ONE_TOO_FEW)
    for (std::size_t i = 0; i + 2 < points.size(); ++i) {  // stops one early
        out.push_back((1 - t) * points[i] + t * points[i + 1]);
    }
#elif defined(BUG_LERP_SWAPPED)
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        out.push_back(t * points[i] + (1 - t) * points[i + 1]);
    }
#else
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        out.push_back((1 - t) * points[i] + t * points[i + 1]);
    }
#endif
    return out;
}

}  // namespace meshedit::student
