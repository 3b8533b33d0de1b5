#pragma once
/// \file
/// A small value-type 3D vector in double precision. The core needs exact, reproducible
/// arithmetic (tests compare positions to 1e-12), so it does not use float or GLM here.

#include <cmath>

namespace meshedit {

/// A texture coordinate (u, v): blends like Vec3 (the attribute carry, properties.h).
struct Vec2 {
    double x = 0.0;
    double y = 0.0;
    constexpr bool operator==(const Vec2&) const = default;
};
constexpr Vec2 operator+(const Vec2& a, const Vec2& b) {
    return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator*(const Vec2& a, double s) {
    return {a.x * s, a.y * s};
}

/// An RGBA colour (each channel 0–1 as files give it): blends like Vec3 (the attribute carry).
struct Vec4 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    double w = 0.0;
    constexpr bool operator==(const Vec4&) const = default;
};
constexpr Vec4 operator+(const Vec4& a, const Vec4& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
constexpr Vec4 operator*(const Vec4& a, double s) {
    return {a.x * s, a.y * s, a.z * s, a.w * s};
}

/// A point or direction in 3D.
struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3& operator+=(const Vec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Vec3& operator-=(const Vec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Vec3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    // True division (not multiplication by 1/s): correctly rounded, so exact cases stay exact.
    constexpr Vec3& operator/=(double s) {
        x /= s;
        y /= s;
        z /= s;
        return *this;
    }

    constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) {
    return a += b;
}
constexpr Vec3 operator-(Vec3 a, const Vec3& b) {
    return a -= b;
}
constexpr Vec3 operator-(const Vec3& a) {
    return {-a.x, -a.y, -a.z};
}
constexpr Vec3 operator*(Vec3 a, double s) {
    return a *= s;
}
constexpr Vec3 operator*(double s, Vec3 a) {
    return a *= s;
}
constexpr Vec3 operator/(Vec3 a, double s) {
    return a /= s;
}

constexpr double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
constexpr double sqrnorm(const Vec3& a) {
    return dot(a, a);
}
inline double distance(const Vec3& a, const Vec3& b) {
    return norm(a - b);
}

/// \return `a` scaled to unit length, or the zero vector when `a` has zero length.
inline Vec3 normalize(const Vec3& a) {
    const double n = norm(a);
    return n > 0.0 ? a / n : Vec3{};
}

/// (a + b) / 2 without overflow: halving is exact, so this is bit for bit 0.5·(a + b)
/// wherever that is finite (and below the subnormal range), and finite near the top of the
/// double range where the sum would overflow (split and collapse at 1e308).
constexpr Vec3 midpoint(const Vec3& a, const Vec3& b) {
    return 0.5 * a + 0.5 * b;
}

/// Linear interpolation `(1-t)·a + t·b`, written so that t = 0 and t = 1 are exact.
constexpr Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
    return (1.0 - t) * a + t * b;
}

inline bool is_finite(const Vec3& a) {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// Axis-aligned bounding box; empty until the first point is added.
struct BoundingBox {
    Vec3 min{INFINITY, INFINITY, INFINITY};
    Vec3 max{-INFINITY, -INFINITY, -INFINITY};

    constexpr void add(const Vec3& p) {
        for (int i = 0; i < 3; ++i) {
            min[i] = p[i] < min[i] ? p[i] : min[i];
            max[i] = p[i] > max[i] ? p[i] : max[i];
        }
    }
    constexpr bool is_empty() const { return min.x > max.x; }
    inline double diagonal() const { return is_empty() ? 0.0 : norm(max - min); }
    constexpr Vec3 center() const { return 0.5 * (min + max); }
};

}  // namespace meshedit
