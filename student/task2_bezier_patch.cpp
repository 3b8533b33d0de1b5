// Task 2: a point of a Bezier patch.
//
// control_points[row][col] is a grid of control points (4 x 4 in the course's .bez files).
// Evaluate the surface at (u, v) by separable 1D de Casteljau:
//
//   1. each row control_points[row] is a Bezier curve in u: evaluate it at u (repeat your
//      step from task 1, in 3D, until one point is left);
//   2. the points you got, one per row, form a curve in v: evaluate it at v.
//
// Hints: u goes along a row (the column index), v across the rows; swapping them gives a
// different point on any patch that is not symmetric. A helper that evaluates one 3D curve
// fully is worth writing first.

#include "meshedit/student/student.h"

namespace meshedit::student {

Vector3D evaluate_patch(const std::vector<std::vector<Vector3D>>& control_points, double u,
                        double v) {
    (void)control_points;
    (void)u;
    (void)v;
    return Vector3D();  // TODO
}

}  // namespace meshedit::student
