// Fuzz target: the .bzc reader, then the curve evaluated by de Casteljau (every level for
// curves small enough) and checked against the Bernstein form.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.h"
#include "meshedit/io/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace meshedit;
    static const bool ready = (fuzz::set_up(), true);
    (void)ready;
    BezierCurve curve;
    try {
        curve = parse_bzc(std::string_view(reinterpret_cast<const char*>(data), size), "f.bzc");
    } catch (const IoError&) {
        return 0;
    }
    fuzz::check(curve.control_points.size() >= 2, "a curve with fewer than 2 points was read");
    for (const double t : {0.0, 0.3, 1.0}) {
        const Vec3 p = curve.evaluate(t);
        fuzz::check(is_finite(p), "a finite curve evaluated to a non-finite point");
        if (curve.control_points.size() <= 64) {
            const auto levels = curve.levels(t);
            fuzz::check(levels.size() == curve.control_points.size() && levels.back().size() == 1,
                        "wrong number of de Casteljau levels");
            fuzz::check(levels.back()[0] == p, "the last level is not B(t)");
        }
    }
    fuzz::check(curve.evaluate(0.0) == curve.control_points.front() &&
                    curve.evaluate(1.0) == curve.control_points.back(),
                "a curve does not interpolate its end points");
    return 0;
}
