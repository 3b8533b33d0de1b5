// Task 1: de Casteljau's algorithm, one step.
//
// Given the n points of one level of de Casteljau's algorithm and the parameter t, return
// the n - 1 points of the next level:
//
//     out[i] = lerp(points[i], points[i + 1], t) = (1 - t) * points[i] + t * points[i + 1]
//
// Hints: the result has exactly one point fewer than the input. t = 0 gives back the first
// n - 1 points, t = 1 the last n - 1: check that your weights are not the wrong way round.
// The grader calls it on curves of 2 to 7 points at several t, t = 0 and t = 1 included, and
// on a single point (no points come out).

#include "meshedit/student/student.h"

namespace meshedit::student {

std::vector<Vector2D> evaluate_step(const std::vector<Vector2D>& points, double t) {
    (void)points;
    (void)t;
    return {};  // TODO
}

}  // namespace meshedit::student
