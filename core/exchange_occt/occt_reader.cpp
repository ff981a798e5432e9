#include "core/exchange_occt/occt_reader.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_OffsetCurve.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESGeom_BSplineCurve.hxx>
#include <IGESGeom_BSplineSurface.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve.hxx>
#include <StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <StepShape_FaceSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>
#include <unistd.h>
#include <vector>

namespace isoparm::exchange_occt {

namespace {

using exchange::CadFormat;
using geom::ErrorCode;

// OCCT's readers read files; the text goes to a private temporary file first (mkstemp: a name
// nobody else can take), removed however the read ends.
class TempFile {
public:
    explicit TempFile(std::string_view text, const char* suffix) {
        const char* dir = std::getenv("TMPDIR");
        path_ = std::string(dir && *dir ? dir : "/tmp") + "/isoparm-import-XXXXXX" + suffix;
        const int fd = mkstemps(path_.data(), static_cast<int>(std::string(suffix).size()));
        if (fd < 0) {
            path_.clear();
            return;
        }
        std::size_t done = 0;
        while (done < text.size()) {
            const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
            if (n <= 0) break;
            done += static_cast<std::size_t>(n);
        }
        ok_ = done == text.size() && ::close(fd) == 0;
    }
    ~TempFile() {
        if (!path_.empty()) std::remove(path_.c_str());
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    bool ok() const { return ok_; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    bool ok_ = false;
};

// OCCT's readers share static parameters (Interface_Static) and print to standard output by
// default: one import at a time, and its messages are not isoparm's output.
std::mutex& reader_mutex() {
    static std::mutex m;
    return m;
}

const char* format_label(CadFormat f) {
    return f == CadFormat::iges ? "IGES" : "STEP";
}

// One face or free edge with the entity it came from.
struct Found {
    Standard_Integer number = 0; // the entity's place in the file (0: unknown, sorts last)
    std::string entity;          // "IGES entity D7", "STEP #42"
    std::string name;
    exchange::ExactShape shape;
    bool converted = false;
    // The file wrote the B-spline in its rational form (IGES 5.3 4.23/4.24 PROP3 = 0; STEP: the
    // complex instance with RATIONAL_B_SPLINE_SURFACE / _CURVE, ISO 10303-42 4.4), even with
    // all weights 1, which OCCT reads as non-rational: the object stays NURBS, as it was.
    bool file_rational = false;
    std::string skip_reason;
};

std::string text_of(const Handle(TCollection_HAsciiString) & s) {
    return s.IsNull() ? std::string() : std::string(s->ToCString());
}

// The entity a shape came from: its number in the file (for the order), its label and name
// (IGES: the DE entity label or a name property, IGES 5.3 sections 2.2.4.4.18 and 4.204;
// STEP: the representation item's name, ISO 10303-43 representation_item.name).
void describe(Found& f, const XSControl_Reader& reader, CadFormat format,
              const TopoDS_Shape& shape) {
    Handle(XSControl_WorkSession) ws = reader.WS();
    Handle(Interface_InterfaceModel) model = ws->Model();
    Handle(Standard_Transient) ent = ws->TransferReader()->EntityFromShapeResult(shape, 1);
    if (ent.IsNull()) ent = ws->TransferReader()->EntityFromShapeResult(shape, -1);
    if (ent.IsNull()) {
        f.entity = std::string(format_label(format)) + " shape";
        return;
    }
    f.number = model->Number(ent);
    f.entity = std::string(format_label(format)) + (format == CadFormat::iges ? " entity " : " ") +
               text_of(model->StringLabel(ent));
    if (format == CadFormat::iges) {
        Handle(IGESData_IGESEntity) e = Handle(IGESData_IGESEntity)::DownCast(ent);
        if (!e.IsNull() && e->HasName())
            f.name = text_of(e->NameValue());
        else if (!e.IsNull() && e->HasShortLabel())
            f.name = text_of(e->ShortLabel());
        if (auto b = Handle(IGESGeom_BSplineSurface)::DownCast(ent); !b.IsNull())
            f.file_rational = !b->IsPolynomial(Standard_True);
        if (auto b = Handle(IGESGeom_BSplineCurve)::DownCast(ent); !b.IsNull())
            f.file_rational = !b->IsPolynomial(Standard_True);
    } else {
        Handle(StepRepr_RepresentationItem) item =
            Handle(StepRepr_RepresentationItem)::DownCast(ent);
        if (!item.IsNull()) f.name = text_of(item->Name());
        Handle(Standard_Transient) geometry = ent;
        if (auto face = Handle(StepShape_FaceSurface)::DownCast(ent); !face.IsNull())
            geometry = face->FaceGeometry();
        f.file_rational =
            !geometry.IsNull() &&
            (geometry->IsKind(
                 STANDARD_TYPE(StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface)) ||
             geometry->IsKind(
                 STANDARD_TYPE(StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve)));
    }
}

std::vector<double> knot_sequence(const TColStd_Array1OfReal& a) {
    std::vector<double> out;
    for (Standard_Integer k = a.Lower(); k <= a.Upper(); ++k) out.push_back(a(k));
    return out;
}

// How many knots of the flat sequence equal the one at index k.
int multiplicity_at(const TColStd_Array1OfReal& knots, Standard_Integer k) {
    int m = 0;
    for (Standard_Integer i = knots.Lower(); i <= knots.Upper(); ++i) m += knots(i) == knots(k);
    return m;
}

// OCCT's readers turn a closed B-spline into its periodic form (poles shared around the seam),
// and SetNotPeriodic unrolls that into unclamped knots running past the domain. Where the seam
// knot has multiplicity >= p the file's spline passed through a control point there: it was a
// clamped closed spline (a revolution, a circle), so it is clamped again to its domain (the
// same poles and knots as the file's, up to rounding). Smooth periodic splines keep the
// unrolled form, which is the file's unclamped one.
void unroll_surface(Handle(Geom_BSplineSurface) & s) {
    const bool u = s->IsUPeriodic(), v = s->IsVPeriodic();
    if (u) s->SetUNotPeriodic();
    if (v) s->SetVNotPeriodic();
    if (!u && !v) return;
    TColStd_Array1OfReal ku(1, s->NbUPoles() + s->UDegree() + 1);
    TColStd_Array1OfReal kv(1, s->NbVPoles() + s->VDegree() + 1);
    s->UKnotSequence(ku);
    s->VKnotSequence(kv);
    const int p = s->UDegree(), q = s->VDegree();
    const bool clamp_u = u && multiplicity_at(ku, 1 + p) >= p && ku(1) != ku(1 + p);
    const bool clamp_v = v && multiplicity_at(kv, 1 + q) >= q && kv(1) != kv(1 + q);
    if (!clamp_u && !clamp_v) return;
    const double u0 = ku(1 + p), u1 = ku(s->NbUPoles() + 1);
    const double v0 = kv(1 + q), v1 = kv(s->NbVPoles() + 1);
    s->Segment(u0, u1, v0, v1);
}

void unroll_curve(Handle(Geom_BSplineCurve) & c) {
    if (!c->IsPeriodic()) return;
    c->SetNotPeriodic();
    TColStd_Array1OfReal k(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(k);
    const int p = c->Degree();
    if (multiplicity_at(k, 1 + p) >= p && k(1) != k(1 + p))
        c->Segment(k(1 + p), k(c->NbPoles() + 1));
}

geom::Surface to_surface(Handle(Geom_BSplineSurface) s) {
    unroll_surface(s);
    geom::Surface out;
    out.type =
        s->IsURational() || s->IsVRational() ? geom::SplineType::nurbs : geom::SplineType::bspline;
    out.degree_u = s->UDegree();
    out.degree_v = s->VDegree();
    out.n_u = s->NbUPoles();
    out.n_v = s->NbVPoles();
    TColStd_Array1OfReal ku(1, out.n_u + out.degree_u + 1), kv(1, out.n_v + out.degree_v + 1);
    s->UKnotSequence(ku);
    s->VKnotSequence(kv);
    out.knots_u = knot_sequence(ku);
    out.knots_v = knot_sequence(kv);
    out.points.resize(static_cast<std::size_t>(out.n_u) * out.n_v);
    out.weights.resize(out.points.size());
    for (int i = 0; i < out.n_u; ++i)
        for (int j = 0; j < out.n_v; ++j) {
            const gp_Pnt p = s->Pole(i + 1, j + 1);
            out.point(i, j) = {p.X(), p.Y(), p.Z()};
            out.weight(i, j) = out.type == geom::SplineType::nurbs ? s->Weight(i + 1, j + 1) : 1.0;
        }
    return out;
}

geom::Curve to_curve(Handle(Geom_BSplineCurve) c) {
    unroll_curve(c);
    geom::Curve out;
    out.type = c->IsRational() ? geom::SplineType::nurbs : geom::SplineType::bspline;
    out.degree = c->Degree();
    TColStd_Array1OfReal k(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(k);
    out.knots = knot_sequence(k);
    for (int i = 1; i <= c->NbPoles(); ++i) {
        const gp_Pnt p = c->Pole(i);
        out.points.push_back({p.X(), p.Y(), p.Z()});
        out.weights.push_back(out.type == geom::SplineType::nurbs ? c->Weight(i) : 1.0);
    }
    return out;
}

// Whether [lo, hi] lies strictly inside [a, b] by more than rounding: only then is the
// geometry cut (a face bounded by its whole surface keeps the surface's exact knots).
bool narrower(double lo, double hi, double a, double b) {
    const double tol = 1e-9 * std::max(1.0, std::abs(b - a));
    return lo > a + tol || hi < b - tol;
}

void face_geometry(Found& f, const TopoDS_Face& face) {
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (s.IsNull()) {
        f.skip_reason = "a face without a surface";
        return;
    }
    Standard_Real u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s); !t.IsNull())
        s = t->BasisSurface();
    const std::string kind = s->DynamicType()->Name();
    if (!Handle(Geom_OffsetSurface)::DownCast(s).IsNull()) {
        f.skip_reason = kind + ": an offset surface has no exact NURBS form";
        return;
    }
    Handle(Geom_BSplineSurface) b;
    if (auto bs = Handle(Geom_BSplineSurface)::DownCast(s); !bs.IsNull()) {
        b = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
        Standard_Real a0, a1, b0, b1;
        b->Bounds(a0, a1, b0, b1);
        if (narrower(u0, u1, a0, a1) || narrower(v0, v1, b0, b1))
            b->Segment(std::max(u0, a0), std::min(u1, a1), std::max(v0, b0), std::min(v1, b1));
    } else {
        // Infinite and periodic surfaces (a plane, a cylinder) are bounded by the face's box.
        Handle(Geom_RectangularTrimmedSurface) box =
            new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1);
        b = GeomConvert::SurfaceToBSplineSurface(box);
    }
    if (b.IsNull()) {
        f.skip_reason = kind + ": OCCT cannot convert it to a B-spline surface";
        return;
    }
    f.shape = to_surface(b);
    f.converted = true;
}

void edge_geometry(Found& f, const TopoDS_Edge& edge) {
    Standard_Real first = 0, last = 0;
    Handle(Geom_Curve) c = BRep_Tool::Curve(edge, first, last);
    if (c.IsNull()) {
        f.skip_reason = "an edge without a 3D curve";
        return;
    }
    if (auto t = Handle(Geom_TrimmedCurve)::DownCast(c); !t.IsNull()) c = t->BasisCurve();
    const std::string kind = c->DynamicType()->Name();
    if (!Handle(Geom_OffsetCurve)::DownCast(c).IsNull()) {
        f.skip_reason = kind + ": an offset curve has no exact NURBS form";
        return;
    }
    Handle(Geom_BSplineCurve) b;
    if (auto bc = Handle(Geom_BSplineCurve)::DownCast(c); !bc.IsNull()) {
        b = Handle(Geom_BSplineCurve)::DownCast(bc->Copy());
        if (narrower(first, last, b->FirstParameter(), b->LastParameter()))
            b->Segment(std::max(first, b->FirstParameter()), std::min(last, b->LastParameter()));
    } else {
        b = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(c, first, last));
    }
    if (b.IsNull()) {
        f.skip_reason = kind + ": OCCT cannot convert it to a B-spline curve";
        return;
    }
    f.shape = to_curve(b);
    f.converted = true;
}

geom::Expected<exchange::ImportResult> read_locked(const std::string& path, CadFormat format) {
    std::unique_ptr<XSControl_Reader> reader;
    if (format == CadFormat::iges) {
        auto r = std::make_unique<IGESControl_Reader>();
        // Keep B-splines as the file has them: the default (1) splits a C0 curve or surface
        // into C1 pieces, which would turn one object into several.
        Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
        reader = std::move(r);
    } else {
        reader = std::make_unique<STEPControl_Reader>();
    }
    const IFSelect_ReturnStatus status = reader->ReadFile(path.c_str());
    if (status != IFSelect_RetDone)
        return geom::make_error(ErrorCode::parse,
                                std::string("OCCT could not read it as ") + format_label(format) +
                                    (status == IFSelect_RetVoid
                                         ? " (no entities)"
                                         : " (not a well-formed file: a syntax error or an "
                                           "unknown entity)"));
    reader->TransferRoots();
    const TopoDS_Shape shape = reader->OneShape();

    std::vector<Found> found;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        Found f;
        describe(f, *reader, format, e.Current());
        face_geometry(f, TopoDS::Face(e.Current()));
        found.push_back(std::move(f));
    }
    for (TopExp_Explorer e(shape, TopAbs_EDGE, TopAbs_FACE); e.More(); e.Next()) {
        Found f;
        describe(f, *reader, format, e.Current());
        edge_geometry(f, TopoDS::Edge(e.Current()));
        found.push_back(std::move(f));
    }
    // File order (stable, so the pieces of one entity keep the reader's order).
    std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
        return (a.number == 0 ? INT_MAX : a.number) < (b.number == 0 ? INT_MAX : b.number);
    });
    exchange::ImportResult out;
    for (Found& f : found) {
        if (f.converted && f.file_rational) {
            if (auto* c = std::get_if<geom::Curve>(&f.shape))
                c->type = geom::SplineType::nurbs;
            else
                std::get<geom::Surface>(f.shape).type = geom::SplineType::nurbs;
        }
        if (f.converted)
            out.objects.push_back({f.name, std::move(f.shape)});
        else
            out.skipped.push_back({f.entity, f.skip_reason});
    }
    // Roots that gave no shape at all (points, annotations, unsupported entities).
    Handle(XSControl_TransferReader) tr = reader->WS()->TransferReader();
    Handle(Interface_InterfaceModel) model = reader->WS()->Model();
    for (Standard_Integer k = 1; k <= reader->NbRootsForTransfer(); ++k) {
        Handle(Standard_Transient) root = reader->RootForTransfer(k);
        if (root.IsNull() || !tr->ShapeResult(root).IsNull()) continue;
        out.skipped.push_back({std::string(format_label(format)) +
                                   (format == CadFormat::iges ? " entity " : " ") +
                                   text_of(model->StringLabel(root)),
                               std::string(root->DynamicType()->Name()) + ": gave no shape"});
    }
    return out;
}

} // namespace

geom::Expected<exchange::ImportResult> read(std::string_view text, CadFormat format) {
    TempFile file(text, format == CadFormat::iges ? ".igs" : ".stp");
    if (!file.ok())
        return geom::make_error(ErrorCode::internal,
                                "cannot write a temporary file for OCCT's reader (TMPDIR)");
    std::lock_guard lock(reader_mutex());
    // OCCT reports through its default messenger on standard output; an import prints nothing.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
    try {
        return read_locked(file.path(), format);
    } catch (const Standard_Failure& e) {
        return geom::make_error(ErrorCode::parse, std::string("OCCT failed reading it: ") +
                                                      e.DynamicType()->Name() + " " +
                                                      e.GetMessageString());
    }
}

void install() {
    exchange::install_cad_reader(&read);
}

} // namespace isoparm::exchange_occt
