#include "core/exchange/import_wire.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace isoparm::exchange {

namespace {

// The stream starts with a magic word (a wrong one is garbage, not a reader's answer) and then
// holds records: a tag byte and its fields, in this machine's byte order (both ends are the same
// program).
constexpr std::string_view magic = "isoparm-import-wire-1\n";

enum Tag : char {
    tag_transferred = 'T',
    tag_curve = 'C',
    tag_surface = 'S',
    tag_trimmed_surface = 'R', // a surface, then its trim (outer loop flag, loops of curves)
    tag_skipped = 'K',
    tag_error = 'E',
    tag_done = 'D',
};

template <class T> void put(std::string& out, T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

void put_text(std::string& out, std::string_view s) {
    put<std::uint64_t>(out, s.size());
    out.append(s);
}

void put_reals(std::string& out, const std::vector<double>& v) {
    put<std::uint64_t>(out, v.size());
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

void put_points(std::string& out, const std::vector<glm::dvec3>& v) {
    put<std::uint64_t>(out, v.size());
    for (const glm::dvec3& p : v) {
        put(out, p.x);
        put(out, p.y);
        put(out, p.z);
    }
}

// Reads fields from the bytes; the first failure makes every later read fail too.
class Cursor {
public:
    explicit Cursor(std::string_view bytes) : rest_(bytes) {}
    bool ok() const { return ok_; }
    bool bad() const { return bad_; }
    bool empty() const { return rest_.empty(); }
    std::size_t left() const { return rest_.size(); }

    template <class T> T get() {
        T value{};
        if (!take(sizeof(T))) return value;
        std::memcpy(&value, taken_, sizeof(T));
        return value;
    }
    std::string text() {
        const auto n = get<std::uint64_t>();
        if (!ok_ || n > rest_.size()) return cut<std::string>();
        take(n);
        return std::string(taken_, n);
    }
    std::vector<double> reals() {
        const auto n = get<std::uint64_t>();
        if (!ok_ || n > rest_.size() / sizeof(double)) return cut<std::vector<double>>();
        std::vector<double> v(n);
        take(n * sizeof(double));
        std::memcpy(v.data(), taken_, n * sizeof(double));
        return v;
    }
    std::vector<glm::dvec3> points() {
        const auto n = get<std::uint64_t>();
        if (!ok_ || n > rest_.size() / (3 * sizeof(double))) return cut<std::vector<glm::dvec3>>();
        std::vector<glm::dvec3> v(n);
        for (glm::dvec3& p : v) {
            p.x = get<double>();
            p.y = get<double>();
            p.z = get<double>();
        }
        return v;
    }
    // A value no writer writes.
    template <class T> T fail() {
        ok_ = false;
        bad_ = true;
        return T{};
    }
    // The bytes end inside a record (the writer died).
    template <class T> T cut() {
        ok_ = false;
        return T{};
    }

private:
    bool take(std::size_t n) {
        if (!ok_ || n > rest_.size()) {
            ok_ = false;
            return false;
        }
        taken_ = rest_.data();
        rest_.remove_prefix(n);
        return true;
    }
    std::string_view rest_;
    const char* taken_ = nullptr;
    bool ok_ = true, bad_ = false;
};

geom::SplineType type_from(std::uint8_t t, Cursor& in) {
    if (t > static_cast<std::uint8_t>(geom::SplineType::nurbs)) return in.fail<geom::SplineType>();
    return static_cast<geom::SplineType>(t);
}

// The records' geometry, in the order ImportWireWriter writes it.
geom::Curve read_curve(Cursor& in) {
    geom::Curve c;
    c.type = type_from(in.get<std::uint8_t>(), in);
    c.degree = in.get<std::int32_t>();
    c.knots = in.reals();
    c.points = in.points();
    c.weights = in.reals();
    return c;
}

geom::Surface read_surface(Cursor& in) {
    geom::Surface s;
    s.type = type_from(in.get<std::uint8_t>(), in);
    s.degree_u = in.get<std::int32_t>();
    s.degree_v = in.get<std::int32_t>();
    s.n_u = in.get<std::int32_t>();
    s.n_v = in.get<std::int32_t>();
    s.knots_u = in.reals();
    s.knots_v = in.reals();
    s.points = in.points();
    s.weights = in.reals();
    return s;
}

// Counts are checked against the bytes left (every curve takes at least 25 bytes), so a garbled
// count never reserves more than the stream holds.
geom::Trim read_trim(Cursor& in) {
    geom::Trim t;
    const auto has_outer = in.get<std::uint8_t>();
    if (has_outer > 1) return in.fail<geom::Trim>();
    const auto loops = in.get<std::uint64_t>();
    if (!in.ok() || loops > in.left() / 8 || (has_outer && loops == 0)) return in.cut<geom::Trim>();
    for (std::uint64_t k = 0; k < loops && in.ok(); ++k) {
        const auto count = in.get<std::uint64_t>();
        if (!in.ok() || count > in.left() / 25) return in.cut<geom::Trim>();
        geom::TrimLoop loop;
        for (std::uint64_t c = 0; c < count && in.ok(); ++c) loop.curves.push_back(read_curve(in));
        if (has_outer && k == 0)
            t.outer = std::move(loop);
        else
            t.holes.push_back(std::move(loop));
    }
    return t;
}

geom::TrimmedSurface read_trimmed_surface(Cursor& in) {
    geom::TrimmedSurface t;
    t.surface = read_surface(in);
    t.trim = read_trim(in);
    return t;
}

// A shape record: its name, then its geometry; kept only when the record is whole.
template <class ReadGeometry>
void read_shape(Cursor& in, ImportWireReading& r, ReadGeometry read_geometry) {
    ImportedShape shape;
    shape.name = in.text();
    auto geometry = read_geometry(in);
    if (!in.ok()) return;
    shape.shape = std::move(geometry);
    r.result.objects.push_back(std::move(shape));
}

} // namespace

ImportWireWriter::ImportWireWriter() : buffer_(magic) {}

void ImportWireWriter::transferred(std::size_t items) {
    buffer_.push_back(tag_transferred);
    put<std::uint64_t>(buffer_, items);
}

namespace {

void put_curve(std::string& out, const geom::Curve& c) {
    put<std::uint8_t>(out, static_cast<std::uint8_t>(c.type));
    put<std::int32_t>(out, c.degree);
    put_reals(out, c.knots);
    put_points(out, c.points);
    put_reals(out, c.weights);
}

void put_surface(std::string& out, const geom::Surface& s) {
    put<std::uint8_t>(out, static_cast<std::uint8_t>(s.type));
    put<std::int32_t>(out, s.degree_u);
    put<std::int32_t>(out, s.degree_v);
    put<std::int32_t>(out, s.n_u);
    put<std::int32_t>(out, s.n_v);
    put_reals(out, s.knots_u);
    put_reals(out, s.knots_v);
    put_points(out, s.points);
    put_reals(out, s.weights);
}

void put_trim(std::string& out, const geom::Trim& t) {
    put<std::uint8_t>(out, t.outer ? 1 : 0);
    put<std::uint64_t>(out, static_cast<std::uint64_t>(t.loop_count()));
    for (int k = 0; k < t.loop_count(); ++k) {
        const geom::TrimLoop& loop = t.loop(k);
        put<std::uint64_t>(out, loop.curves.size());
        for (const geom::Curve& c : loop.curves) put_curve(out, c);
    }
}

} // namespace

void ImportWireWriter::object(const ImportedShape& shape) {
    if (const auto* c = std::get_if<geom::Curve>(&shape.shape)) {
        buffer_.push_back(tag_curve);
        put_text(buffer_, shape.name);
        put_curve(buffer_, *c);
    } else if (const auto* s = std::get_if<geom::Surface>(&shape.shape)) {
        buffer_.push_back(tag_surface);
        put_text(buffer_, shape.name);
        put_surface(buffer_, *s);
    } else {
        const auto& t = std::get<geom::TrimmedSurface>(shape.shape);
        buffer_.push_back(tag_trimmed_surface);
        put_text(buffer_, shape.name);
        put_surface(buffer_, t.surface);
        put_trim(buffer_, t.trim);
    }
}

void ImportWireWriter::skipped(const SkippedEntity& entity) {
    buffer_.push_back(tag_skipped);
    put_text(buffer_, entity.entity);
    put_text(buffer_, entity.reason);
}

void ImportWireWriter::error(const geom::Error& error) {
    buffer_.push_back(tag_error);
    put<std::uint8_t>(buffer_, static_cast<std::uint8_t>(error.code));
    put_text(buffer_, error.message);
}

void ImportWireWriter::done() {
    buffer_.push_back(tag_done);
}

std::string ImportWireWriter::take() {
    std::string out;
    out.swap(buffer_);
    return out;
}

ImportWireReading read_import_wire(std::string_view bytes) {
    ImportWireReading r;
    if (bytes.substr(0, magic.size()) != magic) {
        // The start of the magic word is a stream cut short, anything else is not one.
        r.garbled = bytes.size() >= magic.size() || magic.substr(0, bytes.size()) != bytes;
        return r;
    }
    Cursor in(bytes.substr(magic.size()));
    while (!in.empty() && !r.done) {
        const char tag = in.get<char>();
        switch (tag) {
        case tag_transferred:
            r.items = in.get<std::uint64_t>();
            r.transferred = in.ok();
            break;
        case tag_curve:
            read_shape(in, r, read_curve);
            break;
        case tag_surface:
            read_shape(in, r, read_surface);
            break;
        case tag_trimmed_surface:
            read_shape(in, r, read_trimmed_surface);
            break;
        case tag_skipped: {
            SkippedEntity e;
            e.entity = in.text();
            e.reason = in.text();
            if (!in.ok()) break;
            r.result.skipped.push_back(std::move(e));
            break;
        }
        case tag_error: {
            const auto code = in.get<std::uint8_t>();
            std::string message = in.text();
            if (!in.ok()) break;
            if (code > static_cast<std::uint8_t>(geom::ErrorCode::internal)) {
                in.fail<int>();
                break;
            }
            r.error = geom::make_error(static_cast<geom::ErrorCode>(code), std::move(message));
            break;
        }
        case tag_done:
            r.done = true;
            break;
        default:
            in.fail<int>();
            break;
        }
        if (!in.ok()) {
            // A record cut off where the child died is expected; a value no writer writes is not.
            r.garbled = in.bad();
            break;
        }
    }
    return r;
}

} // namespace isoparm::exchange
