// Bézier curves in homogeneous form: control points (w·x, w), one Eigen vector per
// point (Vector3d for 2D rational curves, Vector4d for 3D), parameter s in [0, 1].
// de Casteljau evaluation and subdivision ([PT] Sec. 1.3, Algorithm A1.5) work on
// homogeneous points, so they are exact for rational curves.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace trimkit::geom {

// The homogeneous point at s (not projected).
template <class V>
V de_casteljau(const std::vector<V>& P, double s) {
    std::vector<V> Q = P;
    for (size_t k = 1; k < Q.size(); ++k)
        for (size_t i = 0; i + k < Q.size(); ++i) Q[i] = (1.0 - s) * Q[i] + s * Q[i + 1];
    return Q.front();
}

// Splits P at s into the pieces over [0, s] and [s, 1], each reparameterised to [0, 1].
template <class V>
void split_bezier(const std::vector<V>& P, double s, std::vector<V>* left, std::vector<V>* right) {
    const size_t n = P.size();
    std::vector<V> Q = P;
    left->assign(n, P[0]);
    right->assign(n, P[0]);
    (*left)[0] = Q[0];
    (*right)[n - 1] = Q[n - 1];
    for (size_t k = 1; k < n; ++k) {
        for (size_t i = 0; i + k < n; ++i) Q[i] = (1.0 - s) * Q[i] + s * Q[i + 1];
        (*left)[k] = Q[0];
        (*right)[n - 1 - k] = Q[n - 1 - k];
    }
}

// The piece of P over [a, b] ⊂ [0, 1], reparameterised to [0, 1].
template <class V>
std::vector<V> bezier_piece(const std::vector<V>& P, double a, double b) {
    std::vector<V> left, right;
    if (b < 1.0) split_bezier(P, b, &left, &right); else left = P;
    if (a <= 0.0) return left;
    std::vector<V> head, tail;
    split_bezier(left, a / b, &head, &tail);
    return tail;
}

// Euclidean point of a homogeneous one: x / w.
template <class V>
Eigen::Matrix<double, V::RowsAtCompileTime - 1, 1> project(const V& h) {
    constexpr int d = V::RowsAtCompileTime - 1;
    return h.template head<d>() / h(d);
}

}  // namespace trimkit::geom
