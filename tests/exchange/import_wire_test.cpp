// How an import's answer crosses from the reader's child process (core/exchange/import_wire.hpp):
// everything sent comes back the same; a stream cut anywhere keeps what arrived whole and never
// claims to be done; bytes that are no records are called garbled, and no size in them is
// trusted beyond the bytes there are.
#include <gtest/gtest.h>

#include "core/exchange/import_wire.hpp"

using namespace isoparm;
using namespace isoparm::exchange;

namespace {

ImportedShape a_surface() {
    geom::Surface s;
    s.type = geom::SplineType::nurbs;
    s.degree_u = 2;
    s.degree_v = 1;
    s.n_u = 3;
    s.n_v = 2;
    s.knots_u = {0, 0, 0, 1, 1, 1};
    s.knots_v = {0, 0, 1, 1};
    for (int i = 0; i < 6; ++i) {
        s.points.push_back({i * 0.5, -i, 1e-300 * i});
        s.weights.push_back(1.0 + i);
    }
    return {"a face", s};
}

ImportedShape a_curve() {
    geom::Curve c;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 3}};
    c.weights = {1, 1};
    return {"", c};
}

std::string a_stream() {
    ImportWireWriter w;
    w.transferred(3);
    w.object(a_surface());
    w.skipped({"STEP #12", "a reason"});
    w.object(a_curve());
    w.done();
    return w.take();
}

TEST(ImportWire, EverythingSentComesBack) {
    const ImportWireReading r = read_import_wire(a_stream());
    EXPECT_TRUE(r.done);
    EXPECT_FALSE(r.garbled);
    EXPECT_TRUE(r.transferred);
    EXPECT_EQ(r.items, 3u);
    ASSERT_EQ(r.result.objects.size(), 2u);
    const auto& s = std::get<geom::Surface>(r.result.objects[0].shape);
    const ImportedShape sent = a_surface();
    const auto& expected = std::get<geom::Surface>(sent.shape);
    EXPECT_EQ(r.result.objects[0].name, "a face");
    EXPECT_EQ(s.type, expected.type);
    EXPECT_EQ(s.degree_u, 2);
    EXPECT_EQ(s.n_u, 3);
    EXPECT_EQ(s.n_v, 2);
    EXPECT_EQ(s.knots_u, expected.knots_u);
    EXPECT_EQ(s.points, expected.points);
    EXPECT_EQ(s.weights, expected.weights);
    const auto& c = std::get<geom::Curve>(r.result.objects[1].shape);
    const ImportedShape sent_curve = a_curve();
    EXPECT_EQ(c.points, std::get<geom::Curve>(sent_curve.shape).points);
    ASSERT_EQ(r.result.skipped.size(), 1u);
    EXPECT_EQ(r.result.skipped[0].entity, "STEP #12");
    EXPECT_EQ(r.result.skipped[0].reason, "a reason");
}

TEST(ImportWire, AStreamCutAnywhereKeepsWhatArrivedWholeAndIsNotDone) {
    const std::string all = a_stream();
    std::size_t last_objects = 0;
    for (std::size_t n = 0; n < all.size(); ++n) {
        const ImportWireReading r = read_import_wire(all.substr(0, n));
        EXPECT_FALSE(r.done) << n;
        EXPECT_FALSE(r.garbled) << n;
        EXPECT_GE(r.result.objects.size(), last_objects) << n;
        last_objects = r.result.objects.size();
    }
    EXPECT_EQ(last_objects, 2u);
}

TEST(ImportWire, AnErrorRecordIsTheReadersError) {
    ImportWireWriter w;
    w.error(geom::make_error(geom::ErrorCode::limit, "too much"));
    w.done();
    const ImportWireReading r = read_import_wire(w.take());
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, geom::ErrorCode::limit);
    EXPECT_EQ(r.error->message, "too much");
    EXPECT_TRUE(r.done);
}

TEST(ImportWire, BytesThatAreNoRecordsAreGarbled) {
    EXPECT_TRUE(read_import_wire("hello").garbled);
    EXPECT_FALSE(read_import_wire("").garbled); // a child that died before writing anything
    ImportWireWriter w;
    const std::string head_only = w.take();
    const ImportWireReading wrong_tag = read_import_wire(head_only + "Q");
    EXPECT_TRUE(wrong_tag.garbled);
    EXPECT_FALSE(wrong_tag.done);
    // A size far beyond the bytes is not allocated: the reading just stops.
    std::string head = head_only;
    head.push_back('K');
    const std::uint64_t huge = std::uint64_t{1} << 60;
    head.append(reinterpret_cast<const char*>(&huge), sizeof huge);
    const ImportWireReading r = read_import_wire(head);
    EXPECT_FALSE(r.done);
    EXPECT_TRUE(r.result.skipped.empty());
}

} // namespace
