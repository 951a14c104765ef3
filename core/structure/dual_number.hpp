// A forward-mode dual number with N derivative directions: x = a + sum_k v_k eps_k, for the exact
// gradients of the co-rotational element energies (corotational.cpp). Only the operations those
// use: arithmetic, sqrt, sin, cos, atan2. Eigen matrices of it work through the NumTraits below.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace orni::structure {

template <int N>
struct Dual {
  using Derivatives = Eigen::Matrix<double, N, 1>;
  double a = 0.0;  ///< value
  Derivatives v = Derivatives::Zero();  ///< derivatives along the N directions

  Dual() = default;
  Dual(double value) : a(value) {}  // NOLINT(google-explicit-constructor): a constant
  Dual(double value, const Derivatives& derivatives) : a(value), v(derivatives) {}
  /// The independent variable number k (0 <= k < N) at `value`.
  static Dual variable(double value, int k) {
    Dual d(value);
    d.v(k) = 1.0;
    return d;
  }

  Dual& operator+=(const Dual& o) {
    a += o.a;
    v += o.v;
    return *this;
  }
  Dual& operator-=(const Dual& o) {
    a -= o.a;
    v -= o.v;
    return *this;
  }
  Dual& operator*=(const Dual& o) {
    v = v * o.a + a * o.v;
    a *= o.a;
    return *this;
  }
  Dual& operator/=(const Dual& o) {
    const double inv = 1.0 / o.a;
    v = (v - (a * inv) * o.v) * inv;
    a *= inv;
    return *this;
  }
};

template <int N> Dual<N> operator-(const Dual<N>& x) { return {-x.a, -x.v}; }
template <int N> Dual<N> operator+(Dual<N> x, const Dual<N>& y) { return x += y; }
template <int N> Dual<N> operator-(Dual<N> x, const Dual<N>& y) { return x -= y; }
template <int N> Dual<N> operator*(Dual<N> x, const Dual<N>& y) { return x *= y; }
template <int N> Dual<N> operator/(Dual<N> x, const Dual<N>& y) { return x /= y; }
template <int N> Dual<N> operator+(Dual<N> x, double y) { x.a += y; return x; }
template <int N> Dual<N> operator+(double y, Dual<N> x) { x.a += y; return x; }
template <int N> Dual<N> operator-(Dual<N> x, double y) { x.a -= y; return x; }
template <int N> Dual<N> operator-(double y, const Dual<N>& x) { return {y - x.a, -x.v}; }
template <int N> Dual<N> operator*(const Dual<N>& x, double y) { return {x.a * y, x.v * y}; }
template <int N> Dual<N> operator*(double y, const Dual<N>& x) { return {x.a * y, x.v * y}; }
template <int N> Dual<N> operator/(const Dual<N>& x, double y) { return {x.a / y, x.v / y}; }
template <int N> Dual<N> operator/(double y, const Dual<N>& x) {
  const double inv = 1.0 / x.a;
  return {y * inv, (-y * inv * inv) * x.v};
}
template <int N> bool operator<(const Dual<N>& x, const Dual<N>& y) { return x.a < y.a; }
template <int N> bool operator>(const Dual<N>& x, const Dual<N>& y) { return x.a > y.a; }
template <int N> bool operator==(const Dual<N>& x, const Dual<N>& y) { return x.a == y.a; }
template <int N> bool operator!=(const Dual<N>& x, const Dual<N>& y) { return x.a != y.a; }

template <int N> Dual<N> sqrt(const Dual<N>& x) {
  const double s = std::sqrt(x.a);
  return {s, x.v * (0.5 / s)};
}
template <int N> Dual<N> sin(const Dual<N>& x) { return {std::sin(x.a), x.v * std::cos(x.a)}; }
template <int N> Dual<N> cos(const Dual<N>& x) { return {std::cos(x.a), x.v * -std::sin(x.a)}; }
template <int N> Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  const double r2 = x.a * x.a + y.a * y.a;
  return {std::atan2(y.a, x.a), (x.a * y.v - y.a * x.v) / r2};
}
template <int N> Dual<N> abs(const Dual<N>& x) { return x.a < 0.0 ? -x : x; }

/// The value of a double or a dual number (for branches on the value).
inline double valueOf(double x) { return x; }
template <int N> double valueOf(const Dual<N>& x) { return x.a; }

}  // namespace orni::structure

namespace Eigen {
template <int N>
struct NumTraits<orni::structure::Dual<N>> : NumTraits<double> {
  using Real = orni::structure::Dual<N>;
  using NonInteger = orni::structure::Dual<N>;
  using Nested = orni::structure::Dual<N>;
  using Literal = orni::structure::Dual<N>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1 + N,
    AddCost = 1 + N,
    MulCost = 1 + 2 * N,
  };
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<orni::structure::Dual<N>, double, BinaryOp> {
  using ReturnType = orni::structure::Dual<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, orni::structure::Dual<N>, BinaryOp> {
  using ReturnType = orni::structure::Dual<N>;
};
}  // namespace Eigen
