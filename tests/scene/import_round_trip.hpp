// Export -> import -> export over every spline object of every scene in assets/scenes: the
// imported objects equal the originals (points, weights and knots within 1e-12 of the
// object's size), and the second export is the first one again: byte for byte, or (where
// `byte_identical` is false) a file that imports to the same numbers within 1e-12.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "core/exchange/iges_writer.hpp"
#include "core/scene/export_document.hpp"
#include "core/scene/import_document.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::test {

inline double points_scale(const std::vector<glm::dvec3>& points) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return std::max(glm::distance(lo, hi), 1.0);
}

inline void expect_near_lists(const std::vector<double>& a, const std::vector<double>& b,
                              double tol, const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t k = 0; k < a.size(); ++k)
        EXPECT_LE(std::abs(a[k] - b[k]), tol) << what << " [" << k << "]";
}

// Same geometry within 1e-12 relative (the type may change: a Bezier comes back a B-spline).
inline void expect_same_geometry(const doc::Object& a, const doc::Object& b,
                                 const std::string& what) {
    ASSERT_EQ(a.kind(), b.kind()) << what;
    const auto points_a = doc::control_points_of(a.shape);
    const auto points_b = doc::control_points_of(b.shape);
    const std::vector<glm::dvec3> pa(points_a.begin(), points_a.end());
    const double tol = 1e-12 * points_scale(pa);
    ASSERT_EQ(points_a.size(), points_b.size()) << what;
    for (std::size_t k = 0; k < points_a.size(); ++k)
        EXPECT_LE(glm::distance(points_a[k], points_b[k]), tol) << what << " point " << k;
    if (const geom::Surface* s = a.surface()) {
        const geom::Surface& t = *b.surface();
        EXPECT_EQ(s->degree_u, t.degree_u) << what;
        EXPECT_EQ(s->degree_v, t.degree_v) << what;
        EXPECT_EQ(s->n_u, t.n_u) << what;
        expect_near_lists(s->knots_u, t.knots_u, 1e-12, what + " knots u");
        expect_near_lists(s->knots_v, t.knots_v, 1e-12, what + " knots v");
        expect_near_lists(s->weights, t.weights, 1e-12, what + " weights");
    } else {
        const geom::Curve& c = *a.curve();
        const geom::Curve& d = *b.curve();
        EXPECT_EQ(c.degree, d.degree) << what;
        expect_near_lists(c.knots, d.knots, 1e-12, what + " knots");
        expect_near_lists(c.weights, d.weights, 1e-12, what + " weights");
    }
}

// Returns the number of scenes whose second export was byte-identical to the first.
inline int expect_round_trips(scene::ExportFormat export_format, scene::ImportFormat format,
                              bool byte_identical) {
    const std::filesystem::path scenes =
        std::filesystem::path(ISOPARM_SOURCE_DIR) / "assets/scenes";
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(scenes))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    EXPECT_FALSE(files.empty());
    int identical = 0, objects_seen = 0;
    for (const auto& file : files) {
        const std::string name = file.filename().string();
        const auto doc = scene::load_scene(file.string());
        EXPECT_TRUE(doc) << name;
        if (!doc) continue;
        std::vector<const doc::Object*> originals;
        const bool exact_weights = format != scene::ImportFormat::obj;
        for (const doc::Object& o : doc->objects) {
            // Neither has an exact form in the exchange formats (export refuses them).
            if (o.kind() == doc::ObjectKind::implicit || o.kind() == doc::ObjectKind::triangle)
                continue;
            if (exact_weights) {
                const exchange::ExactShape shape = o.surface() ? exchange::ExactShape(*o.surface())
                                                               : exchange::ExactShape(*o.curve());
                if (!exchange::check_positive_weights(shape)) continue;
            }
            originals.push_back(&o);
        }
        if (originals.empty()) continue;
        objects_seen += static_cast<int>(originals.size());
        scene::ExportOptions options;
        options.format = export_format;
        options.name = file.stem().string();
        const auto first = scene::export_document(originals, options);
        EXPECT_TRUE(first) << name << ": " << first.error().message;
        if (!first) continue;
        const auto imported = scene::import_text(first->bytes, format);
        EXPECT_TRUE(imported) << name << ": " << imported.error().message;
        if (!imported) continue;
        EXPECT_TRUE(imported->skipped.empty()) << name << ": " << imported->skipped.front();
        EXPECT_EQ(imported->objects.size(), originals.size()) << name;
        if (imported->objects.size() != originals.size()) continue;
        std::vector<const doc::Object*> again;
        for (std::size_t k = 0; k < originals.size(); ++k) {
            expect_same_geometry(*originals[k], imported->objects[k],
                                 name + " object " + std::to_string(k) + " '" + originals[k]->name +
                                     "'");
            again.push_back(&imported->objects[k]);
        }
        const auto second = scene::export_document(again, options);
        EXPECT_TRUE(second) << name << ": " << second.error().message;
        if (!second) continue;
        if (second->bytes == first->bytes) {
            ++identical;
            continue;
        }
        EXPECT_FALSE(byte_identical) << name << ": the second export differs from the first";
        const auto reimported = scene::import_text(second->bytes, format);
        EXPECT_TRUE(reimported) << name;
        if (!reimported) continue;
        EXPECT_EQ(reimported->objects.size(), originals.size()) << name;
        for (std::size_t k = 0; k < std::min(originals.size(), reimported->objects.size()); ++k)
            expect_same_geometry(imported->objects[k], reimported->objects[k],
                                 name + " second export, object " + std::to_string(k));
    }
    EXPECT_GT(objects_seen, 10);
    return identical;
}

} // namespace isoparm::test
