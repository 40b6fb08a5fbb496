// A controls engineer's C++ application on the C++ layer (docs/c-api.md, "C++"): six book
// kernels called through rigidsym::eigen with column-major Eigen arguments, as an
// application holds them. Reads each kernel's inputs (row-major components, one sample after
// another) from DIR/<kernel>.<f32|f64>.in, writes per sample the status (int32) and the
// outputs' bits in the layer's order to DIR/<kernel>.<f32|f64>.<tag>.out.
// Built and compared across compilers and flags by benchmarks/engineer_app.py.
// SPDX-License-Identifier: MIT
#include <Eigen/Dense>
#include "rigidsym_c.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

template <class S> std::vector<S> read_all(const std::string &path) {
    std::vector<S> v;
    std::FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) return v;
    S x;
    while (std::fread(&x, sizeof x, 1, f) == 1) v.push_back(x);
    std::fclose(f);
    return v;
}

template <class S> struct Sink {
    std::vector<std::int32_t> status;
    std::vector<S> out;
    template <class M> void put(const M &m) {
        for (Eigen::Index i = 0; i < m.rows(); ++i)
            for (Eigen::Index j = 0; j < m.cols(); ++j) out.push_back(m(i, j));
    }
    void put(S x) { out.push_back(x); }
    bool write(const std::string &path) const {
        std::FILE *f = std::fopen(path.c_str(), "wb");
        if (!f) return false;
        const std::int32_t n = static_cast<std::int32_t>(status.size());
        bool ok = std::fwrite(&n, sizeof n, 1, f) == 1 &&
                  std::fwrite(status.data(), sizeof(std::int32_t), status.size(), f) ==
                      status.size() &&
                  std::fwrite(out.data(), sizeof(S), out.size(), f) == out.size();
        return std::fclose(f) == 0 && ok;
    }
};

template <class S> using M3 = Eigen::Matrix<S, 3, 3>;  // column-major, Eigen's default
template <class S> using V3 = Eigen::Matrix<S, 3, 1>;
template <class S> using V6 = Eigen::Matrix<S, 6, 1>;

template <class S> M3<S> mat3(const S *p) {
    M3<S> m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = p[3 * i + j];
    return m;
}
template <class S> V3<S> vec3(const S *p) { return V3<S>(p[0], p[1], p[2]); }

template <class S> int run(const std::string &dir, const std::string &suffix,
                           const std::string &tag) {
    namespace rs = rigidsym::eigen;
    int failures = 0;
    auto path = [&](const char *k, const char *ext) {
        return dir + "/" + k + "." + suffix + ext;
    };
    auto finish = [&](const char *k, const Sink<S> &s) {
        if (!s.write(path(k, ("." + tag + ".out").c_str()))) {
            std::fprintf(stderr, "cannot write %s\n", k);
            ++failures;
        }
    };
    {
        const char *k = "rotation_from_natural_invariants";
        std::vector<S> in = read_all<S>(path(k, ".in"));
        Sink<S> s;
        for (std::size_t i = 0; i + 4 <= in.size(); i += 4) {
            auto r = rs::rotation_from_natural_invariants(vec3(&in[i]), in[i + 3]);
            s.status.push_back(static_cast<std::int32_t>(r.status));
            s.put(r.Q);
        }
        finish(k, s);
    }
    {
        const char *k = "rotation_vector_from_rotation";
        std::vector<S> in = read_all<S>(path(k, ".in"));
        Sink<S> s;
        for (std::size_t i = 0; i + 9 <= in.size(); i += 9) {
            auto r = rs::rotation_vector_from_rotation(mat3(&in[i]));
            s.status.push_back(static_cast<std::int32_t>(r.status));
            s.put(r.w);
        }
        finish(k, s);
    }
    {
        const char *k = "natural_invariants_from_rotation";
        std::vector<S> in = read_all<S>(path(k, ".in"));
        Sink<S> s;
        for (std::size_t i = 0; i + 9 <= in.size(); i += 9) {
            auto r = rs::natural_invariants_from_rotation(mat3(&in[i]));
            s.status.push_back(static_cast<std::int32_t>(r.status));
            s.put(r.e);
            s.put(r.phi);
        }
        finish(k, s);
    }
    {
        const char *k = "screw_of_displacement";
        std::vector<S> in = read_all<S>(path(k, ".in"));
        Sink<S> s;
        for (std::size_t i = 0; i + 15 <= in.size(); i += 15) {
            auto r = rs::screw_of_displacement(mat3(&in[i]), vec3(&in[i + 9]),
                                               vec3(&in[i + 12]));
            s.status.push_back(static_cast<std::int32_t>(r.status));
            s.put(r.e);
            s.put(r.phi);
            s.put(r.p0);
            s.put(r.pitch);
            s.put(r.plucker);
        }
        finish(k, s);
    }
    {
        const char *k = "twist_transfer";
        std::vector<S> in = read_all<S>(path(k, ".in"));
        Sink<S> s;
        for (std::size_t i = 0; i + 12 <= in.size(); i += 12) {
            V6<S> t;
            for (int j = 0; j < 6; ++j) t(j) = in[i + j];
            auto r = rs::twist_transfer(t, vec3(&in[i + 6]), vec3(&in[i + 9]));
            s.status.push_back(static_cast<std::int32_t>(r.status));
            s.put(r.t_P);
        }
        finish(k, s);
    }
    {
        const char *k = "newton_euler_wrench";
        std::vector<S> in = read_all<S>(path(k, ".in"));
        Sink<S> s;
        for (std::size_t i = 0; i + 19 <= in.size(); i += 19) {
            auto r = rs::newton_euler_wrench(mat3(&in[i]), in[i + 9], vec3(&in[i + 10]),
                                             vec3(&in[i + 13]), vec3(&in[i + 16]));
            s.status.push_back(static_cast<std::int32_t>(r.status));
            s.put(r.w);
        }
        finish(k, s);
    }
    return failures;
}

}  // namespace

int main(int argc, char **argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s DIR TAG\n", argv[0]);
        return 2;
    }
    return run<double>(argv[1], "f64", argv[2]) + run<float>(argv[1], "f32", argv[2]);
}
