#include "core/exchange_occt/occt_read.hpp"

#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESGeom_BSplineCurve.hxx>
#include <IGESGeom_BSplineSurface.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <Standard_OutOfMemory.hxx>
#include <StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve.hxx>
#include <StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface.hxx>
#include <StepRepr_MappedItem.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <StepRepr_RepresentationRelationshipWithTransformation.hxx>
#include <StepShape_ContextDependentShapeRepresentation.hxx>
#include <StepShape_FaceSurface.hxx>
#include <StepShape_GeometricSet.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_TShape.hxx>
#include <TransferBRep.hxx>
#include <Transfer_Binder.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <climits>
#include <cstring>
#include <istream>
#include <memory>
#include <set>
#include <streambuf>
#include <unordered_map>

#include "core/exchange/import_wire.hpp"
#include "core/exchange_occt/occt_convert.hpp"
#include "core/exchange_occt/occt_step_diagnosis.hpp"

namespace isoparm::exchange_occt {

namespace {

using exchange::CadFormat;
using geom::ErrorCode;

const char* format_label(CadFormat f) {
    return f == CadFormat::iges ? "IGES" : "STEP";
}

std::string text_of(const Handle(TCollection_HAsciiString) & s) {
    return s.IsNull() ? std::string() : std::string(s->ToCString());
}

std::string trimmed(const char* text) {
    std::string s(text ? text : "");
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

// "IGES entity D7", "STEP #42": how messages name an entity of the file.
std::string entity_label(CadFormat format, const Handle(Interface_InterfaceModel) & model,
                         const Handle(Standard_Transient) & ent) {
    return std::string(format_label(format)) + (format == CadFormat::iges ? " entity " : " ") +
           text_of(model->StringLabel(ent));
}

// The text as a stream for STEPControl_Reader::ReadStream, without a copy.
class MemoryBuffer : public std::streambuf {
public:
    explicit MemoryBuffer(std::string_view text) {
        char* p = const_cast<char*>(text.data()); // read only: the get area is never written
        setg(p, p, p + text.size());
    }

protected:
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
        char* base = dir == std::ios_base::beg   ? eback()
                     : dir == std::ios_base::cur ? gptr()
                                                 : egptr();
        char* to = base + off;
        if (to < eback() || to > egptr()) return pos_type(off_type(-1));
        setg(eback(), to, egptr());
        return pos_type(to - eback());
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
        return seekoff(off_type(pos), std::ios_base::beg, which);
    }
};

// One face or free edge with the entity it came from.
struct Item {
    TopoDS_Shape shape;
    bool face = true;
    // Read face by face (ReadPlan::careful): the entity to transfer first; its faces (or, for a
    // geometric set, its edges) are then the item's shapes.
    Handle(Standard_Transient) transfer;
    Standard_Integer number = 0; // the entity's place in the file (0: unknown, sorts last)
    std::string entity;
    std::string trimmed(const char* text) {
        std::string s(text ? text : "");
        const auto first = s.find_first_not_of(" \t\r\n");
        if (first == std::string::npos) return "";
        return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
    }

    // "IGES entity D7", "STEP #42"
    std::string name;
    // The file wrote the B-spline in its rational form (IGES 5.3 4.23/4.24 PROP3 = 0; STEP: the
    // complex instance with RATIONAL_B_SPLINE_SURFACE / _CURVE, ISO 10303-42 4.4), even with
    // all weights 1, which OCCT reads as non-rational: the object stays NURBS, as it was.
    bool file_rational = false;
    // STEP: what is wrong with the B-spline the file gives (occt_step_diagnosis.hpp) though
    // OCCT transferred it: it mends some faults on its own (knots that decrease are merged into
    // others), which would import a surface the file does not describe. Such an item is
    // skipped with this reason.
    std::string file_problem;
};

// The entity whose transfer gave each shape, found once for all shapes (asking the transfer
// reader shape by shape searches all its results each time: quadratic in a big file).
class ShapeOwners {
public:
    explicit ShapeOwners(const Handle(Transfer_TransientProcess) & tp) {
        for (Standard_Integer i = 1; i <= tp->NbMapped(); ++i) {
            for (Handle(Transfer_Binder) b = tp->MapItem(i); !b.IsNull(); b = b->NextResult()) {
                const TopoDS_Shape s = TransferBRep::ShapeResult(b);
                if (!s.IsNull()) owners_.emplace(s.TShape().get(), tp->Mapped(i));
            }
        }
    }
    Handle(Standard_Transient) of(const TopoDS_Shape& s) const {
        const auto it = owners_.find(s.TShape().get());
        return it == owners_.end() ? Handle(Standard_Transient)() : it->second;
    }

private:
    std::unordered_map<const TopoDS_TShape*, Handle(Standard_Transient)> owners_;
};

// Its number, label and name (IGES: the DE entity label or a name property, IGES 5.3 sections
// 2.2.4.4.18 and 4.204; STEP: the representation item's name, ISO 10303-43
// representation_item.name).
void describe(Item& item, CadFormat format, const Handle(Interface_InterfaceModel) & model,
              const Handle(Standard_Transient) & ent) {
    if (ent.IsNull()) {
        item.entity = std::string(format_label(format)) + (item.face ? " face" : " edge");
        return;
    }
    item.number = model->Number(ent);
    item.entity = entity_label(format, model, ent);
    if (format == CadFormat::iges) {
        Handle(IGESData_IGESEntity) e = Handle(IGESData_IGESEntity)::DownCast(ent);
        if (!e.IsNull() && e->HasName())
            item.name = text_of(e->NameValue());
        else if (!e.IsNull() && e->HasShortLabel())
            item.name = text_of(e->ShortLabel());
        if (auto b = Handle(IGESGeom_BSplineSurface)::DownCast(ent); !b.IsNull())
            item.file_rational = !b->IsPolynomial(Standard_True);
        if (auto b = Handle(IGESGeom_BSplineCurve)::DownCast(ent); !b.IsNull())
            item.file_rational = !b->IsPolynomial(Standard_True);
        return;
    }
    Handle(StepRepr_RepresentationItem) rep = Handle(StepRepr_RepresentationItem)::DownCast(ent);
    if (!rep.IsNull()) item.name = text_of(rep->Name());
    Handle(Standard_Transient) geometry = ent;
    if (auto face = Handle(StepShape_FaceSurface)::DownCast(ent); !face.IsNull())
        geometry = face->FaceGeometry();
    if (!geometry.IsNull()) item.file_problem = diagnose_step_bspline(geometry);
    item.file_rational =
        !geometry.IsNull() &&
        (geometry->IsKind(
             STANDARD_TYPE(StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface)) ||
         geometry->IsKind(STANDARD_TYPE(StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve)));
}

// What has been said about which entities: each entity once, and a file with many problems
// lists the first ones and how many more.
struct Listed {
    std::set<Standard_Integer> entities;
    std::size_t problems = 0, more = 0;
    static constexpr std::size_t max_problems = 200;
    // Whether a problem about entity `number` (0: none in particular) is to be written.
    bool take(Standard_Integer number) {
        if (number != 0 && !entities.insert(number).second) return false;
        if (problems >= max_problems) {
            ++more;
            return false;
        }
        ++problems;
        return true;
    }
};

// Entities OCCT's checks failed (reading: syntax and references; transfer: degree over 25,
// bad knots, weights that are not positive, a 2D point in 3D geometry, ...), one entry each
// with OCCT's own words, except those already listed.
void list_failed_checks(const Interface_CheckIterator& checks, const char* stage, CadFormat format,
                        const Handle(Interface_InterfaceModel) & model, Listed& listed,
                        exchange::ImportWireWriter& out) {
    for (checks.Start(); checks.More(); checks.Next()) {
        const Handle(Interface_Check)& check = checks.Value();
        if (check.IsNull() || !check->HasFailed()) continue;
        Standard_Integer number = checks.Number();
        Handle(Standard_Transient) ent = check->Entity();
        if (number == 0 && !ent.IsNull()) number = model->Number(ent);
        if (!listed.take(number)) continue;
        std::string reason = std::string(stage) + ":";
        for (Standard_Integer k = 1; k <= check->NbFails(); ++k)
            reason += (k > 1 ? ";" : "") + std::string(" ") + trimmed(check->CFail(k));
        if (format == CadFormat::step && number > 0 && number <= model->NbEntities())
            if (const std::string why = diagnose_step_bspline(model->Value(number)); !why.empty())
                reason += " (" + why + ")";
        std::string entity;
        if (number > 0 && number <= model->NbEntities())
            entity = entity_label(format, model, model->Value(number));
        else
            entity = std::string(format_label(format)) + " file";
        out.skipped({entity, reason});
    }
}

// Read face by face: every face entity of the file (ISO 10303-42 face_surface, which
// advanced_face is) and every geometric set (free curves and surfaces), each transferred on its
// own, so that an entity that crashes OCCT's transfer costs that entity only. Faces keep their
// file's units (the actor finds each one's representation context); what would place them (an
// assembly's transformations) is not applied, so a file with any is not read this way: the
// reason is returned.
std::string careful_items(const Handle(Interface_InterfaceModel) & model,
                          std::vector<Item>& items) {
    for (Standard_Integer n = 1; n <= model->NbEntities(); ++n) {
        const Handle(Standard_Transient)& ent = model->Value(n);
        if (ent.IsNull()) continue;
        if (ent->IsKind(STANDARD_TYPE(StepRepr_MappedItem)) ||
            ent->IsKind(STANDARD_TYPE(StepShape_ContextDependentShapeRepresentation)) ||
            ent->IsKind(STANDARD_TYPE(StepRepr_RepresentationRelationshipWithTransformation)))
            return "it is an assembly (#" + std::to_string(n) +
                   " places a part), which is not "
                   "read face by face";
        const bool face = ent->IsKind(STANDARD_TYPE(StepShape_FaceSurface));
        if (!face && !ent->IsKind(STANDARD_TYPE(StepShape_GeometricSet))) continue;
        Item item;
        item.face = face;
        item.transfer = ent;
        items.push_back(std::move(item));
    }
    return "";
}

// The item's objects: its shape converted, or (read face by face) the entity transferred and
// each of its faces or edges converted. OCCT's exceptions stay with the item.
std::vector<Converted> convert_item(const Item& item, XSControl_Reader& reader) {
    if (item.transfer.IsNull())
        return {item.face ? convert_face(TopoDS::Face(item.shape))
                          : convert_edge(TopoDS::Edge(item.shape))};
    TopoDS_Shape shape;
    try {
        if (reader.TransferEntity(item.transfer))
            shape = reader.WS()->TransferReader()->ShapeResult(item.transfer);
    } catch (const Standard_Failure& e) {
        return {{std::nullopt, std::string("OCCT failed transferring it: ") +
                                   e.DynamicType()->Name() + " " + e.GetMessageString()}};
    }
    std::vector<Converted> out;
    if (shape.IsNull()) return out; // the transfer's check list says why
    for (TopExp_Explorer e(shape, item.face ? TopAbs_FACE : TopAbs_EDGE); e.More(); e.Next())
        out.push_back(item.face ? convert_face(TopoDS::Face(e.Current()))
                                : convert_edge(TopoDS::Edge(e.Current())));
    if (!item.face)
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
            out.push_back(convert_face(TopoDS::Face(e.Current())));
    return out;
}

std::unique_ptr<XSControl_Reader> make_reader(CadFormat format) {
    if (format == CadFormat::step) return std::make_unique<STEPControl_Reader>();
    auto reader = std::make_unique<IGESControl_Reader>();
    // Keep B-splines as the file has them: the default (1) splits a C0 curve or surface into C1
    // pieces, which would turn one object into several.
    Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
    return reader;
}

// A shape the file declares rational stays `nurbs` even where its weights are all 1.
void mark_rational(exchange::ExactShape& shape) {
    if (auto* curve = std::get_if<geom::Curve>(&shape))
        curve->type = geom::SplineType::nurbs;
    else if (auto* surface = std::get_if<geom::Surface>(&shape))
        surface->type = geom::SplineType::nurbs;
    else
        std::get<geom::TrimmedSurface>(shape).surface.type = geom::SplineType::nurbs;
}

// An item's converted shapes into the stream: each shape, or why it is left out; a face that
// came without its trim loops also says why in `skipped`.
void send_item(const Item& item, XSControl_Reader& reader, exchange::ImportWireWriter& out) {
    for (Converted& c : convert_item(item, reader)) {
        if (!c.shape) {
            out.skipped({item.entity, c.skip_reason});
            continue;
        }
        if (!c.note.empty()) out.skipped({item.entity, c.note});
        if (item.file_rational) mark_rational(*c.shape);
        out.object({item.name, std::move(*c.shape)});
    }
}

void read_and_send(const ReadPlan& plan, ReadProgress& progress, exchange::ImportWireWriter& out,
                   const std::function<void(bool)>& flush,
                   std::unique_ptr<XSControl_Reader>& reader) {
    const CadFormat format = plan.format;
    reader = make_reader(format);
    progress.stage = ReadProgress::reading;
    IFSelect_ReturnStatus status;
    if (format == CadFormat::step) {
        MemoryBuffer buffer(plan.text);
        std::istream stream(&buffer);
        status = reader->ReadStream("import.step", stream);
    } else {
        status = reader->ReadFile(plan.path.c_str());
    }
    if (status != IFSelect_RetDone) {
        out.error(geom::make_error(
            ErrorCode::parse,
            std::string("OCCT could not read it as ") + format_label(format) +
                (status == IFSelect_RetVoid ? " (no entities)"
                                            : " (not a well-formed file: a syntax error or an "
                                              "unknown entity)")));
        return;
    }
    Handle(XSControl_WorkSession) ws = reader->WS();
    Handle(Interface_InterfaceModel) model = ws->Model();
    // The entities the text check took out are listed by the caller, with its reason.
    Listed listed;
    for (const exchange::BadEntity& bad : plan.bad_entities)
        listed.entities.insert((bad.directory_line + 1) / 2);
    list_failed_checks(ws->ModelCheckList(Standard_False), "could not be read", format, model,
                       listed, out);

    Handle(XSControl_TransferReader) tr = ws->TransferReader();
    std::vector<Item> items;
    if (!plan.careful) {
        progress.stage = ReadProgress::transferring;
        reader->TransferRoots();
        const TopoDS_Shape shape = reader->OneShape();
        const ShapeOwners owners(tr->TransientProcess());
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
            Item item;
            item.shape = e.Current();
            describe(item, format, model, owners.of(e.Current()));
            items.push_back(std::move(item));
        }
        for (TopExp_Explorer e(shape, TopAbs_EDGE, TopAbs_FACE); e.More(); e.Next()) {
            Item item;
            item.shape = e.Current();
            item.face = false;
            describe(item, format, model, owners.of(e.Current()));
            items.push_back(std::move(item));
        }
    } else if (std::string why = careful_items(model, items); !why.empty()) {
        out.error(geom::make_error(ErrorCode::parse, why));
        return;
    } else {
        for (Item& item : items) describe(item, format, model, item.transfer);
    }
    // File order (stable, so the pieces of one entity keep the reader's order).
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
        return (a.number == 0 ? INT_MAX : a.number) < (b.number == 0 ? INT_MAX : b.number);
    });

    progress.items = static_cast<std::int64_t>(items.size());
    progress.stage = ReadProgress::converting;
    out.transferred(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) {
        Item& item = items[k];
        const std::size_t n = std::min(item.entity.size(), sizeof(progress.entity) - 1);
        std::memcpy(progress.entity, item.entity.data(), n);
        progress.entity[n] = '\0';
        progress.item = static_cast<std::int64_t>(k);
        if (item.number != 0) listed.entities.insert(item.number);
        if (const auto skip =
                std::find_if(plan.skip.begin(), plan.skip.end(),
                             [&](const SkipItem& s) { return s.item == progress.item; });
            skip != plan.skip.end()) {
            out.skipped({item.entity, skip->reason});
        } else if (!item.file_problem.empty()) {
            out.skipped({item.entity, "not read: " + item.file_problem});
        } else {
            send_item(item, *reader, out);
        }
        flush(false);
    }

    progress.stage = ReadProgress::listing;
    if (Handle(Transfer_TransientProcess) tp = tr->TransientProcess(); !tp.IsNull())
        list_failed_checks(tp->CheckList(Standard_True), "OCCT could not transfer it", format,
                           model, listed, out);
    // Roots that gave no shape at all (points, annotations, unsupported entities).
    for (Standard_Integer k = 1; !plan.careful && k <= reader->NbRootsForTransfer(); ++k) {
        Handle(Standard_Transient) root = reader->RootForTransfer(k);
        if (root.IsNull() || !tr->ShapeResult(root).IsNull()) continue;
        if (!listed.take(model->Number(root))) continue;
        out.skipped({entity_label(format, model, root),
                     std::string(root->DynamicType()->Name()) + ": gave no shape"});
    }
    if (listed.more > 0)
        out.skipped({std::to_string(listed.more) + " more entities",
                     "not listed (the first " + std::to_string(Listed::max_problems) + " are)"});
}

} // namespace

void read_with_occt(const ReadPlan& plan, ReadProgress& progress,
                    const std::function<void(std::string&& bytes, bool last)>& send) {
    // OCCT reports through its default messenger on standard output; an import prints nothing.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
    exchange::ImportWireWriter out;
    constexpr std::size_t chunk = std::size_t{1} << 20;
    auto flush = [&](bool last) {
        if (last || out.size() >= chunk) send(out.take(), last);
    };
    send(out.take(), false); // the stream's magic word: what follows is records
    // Kept until after the last record is sent: the sandbox's child may end the process there,
    // without tearing down OCCT's model of the file (5% of reading a 64 MB STEP file).
    std::unique_ptr<XSControl_Reader> reader;
    try {
        read_and_send(plan, progress, out, flush, reader);
    } catch (const Standard_OutOfMemory&) {
        throw std::bad_alloc();
    } catch (const Standard_Failure& e) {
        out.error(geom::make_error(ErrorCode::parse, std::string("OCCT failed reading it: ") +
                                                         e.DynamicType()->Name() + " " +
                                                         e.GetMessageString()));
    }
    progress.stage = ReadProgress::finished;
    out.done();
    flush(true);
}

} // namespace isoparm::exchange_occt
