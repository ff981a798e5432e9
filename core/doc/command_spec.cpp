// make_command: each spec to the factory that builds its command.
#include "core/doc/command_spec.hpp"

#include "core/doc/commands.hpp"
#include "core/doc/commands_construction.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/commands_multires.hpp"
#include "core/doc/commands_points.hpp"
#include "core/doc/commands_triangle.hpp"
#include "core/doc/commands_trim.hpp"

namespace isoparm::doc {

namespace {

struct Build {
    std::unique_ptr<Command> operator()(AddObjectSpec& s) {
        return add_object(std::move(s.object));
    }
    std::unique_ptr<Command> operator()(AddObjectsSpec& s) {
        return add_objects(std::move(s.objects), std::move(s.label));
    }
    std::unique_ptr<Command> operator()(RemoveObjectSpec& s) { return remove_object(s.id); }
    std::unique_ptr<Command> operator()(RenameObjectSpec& s) {
        return rename_object(s.id, std::move(s.name));
    }
    std::unique_ptr<Command> operator()(SetVisibleSpec& s) { return set_visible(s.id, s.visible); }
    std::unique_ptr<Command> operator()(SetTrimSpec& s) {
        return set_trim(s.id, std::move(s.trim));
    }
    std::unique_ptr<Command> operator()(RemoveTrimSpec& s) { return remove_trim(s.id); }
    std::unique_ptr<Command> operator()(EditShapeSpec& s) {
        return edit_shape(s.id, std::move(s.shape), std::move(s.label), std::move(s.merge_key));
    }
    std::unique_ptr<Command> operator()(EditPointSpec& s) { return edit_point(std::move(s)); }
    std::unique_ptr<Command> operator()(MoveKnotSpec& s) {
        return move_knot_run(s.id, s.dir, s.k, s.count, s.value);
    }
    std::unique_ptr<Command> operator()(TransformSpec& s) {
        return transform_object(s.id, s.matrix, std::move(s.label));
    }
    std::unique_ptr<Command> operator()(InsertKnotSpec& s) {
        return insert_knot(s.id, s.dir, s.t, s.times);
    }
    std::unique_ptr<Command> operator()(ElevateDegreeSpec& s) {
        return elevate_degree(s.id, s.dir, s.times);
    }
    std::unique_ptr<Command> operator()(SplitSpec& s) { return split_object(s.id, s.dir, s.t); }
    std::unique_ptr<Command> operator()(ConformBordersSpec& s) { return conform_borders(s.group); }
    std::unique_ptr<Command> operator()(SetColorsSpec& s) { return set_colors(s.colors); }
    std::unique_ptr<Command> operator()(InsertCurvePointSpec& s) {
        return insert_curve_point(s.id, s.i, s.position);
    }
    std::unique_ptr<Command> operator()(DeleteCurvePointSpec& s) {
        return delete_curve_point(s.id, s.i);
    }
    std::unique_ptr<Command> operator()(MoveCurvePointSpec& s) {
        return move_curve_point(s.id, s.i, s.position);
    }
    std::unique_ptr<Command> operator()(SetCurveDegreeSpec& s) {
        return set_curve_degree(s.id, s.degree);
    }
    std::unique_ptr<Command> operator()(SetCurveKnotModeSpec& s) {
        return set_curve_knot_mode(s.id, s.mode);
    }
    std::unique_ptr<Command> operator()(SetCurvePlaneSpec& s) {
        return set_curve_plane(s.id, s.plane, s.carry_points);
    }
    std::unique_ptr<Command> operator()(MakeCompatibleSpec& s) {
        return make_curves_compatible(std::move(s.ids));
    }
    std::unique_ptr<Command> operator()(RemoveKnotSpec& s) {
        return remove_knot(s.id, s.dir, s.t, s.times, s.tolerance);
    }
    std::unique_ptr<Command> operator()(ReduceDegreeSpec& s) {
        return reduce_degree(s.id, s.dir, s.tolerance);
    }
    std::unique_ptr<Command> operator()(SplitKnotSpec& s) {
        return split_knot(s.id, s.dir, s.t, s.delta);
    }
    std::unique_ptr<Command> operator()(CloseSpec& s) { return close_object(s.id, s.dir); }
    std::unique_ptr<Command> operator()(ConvertSpec& s) {
        return convert_object(s.id, s.to, s.reset_weights);
    }
    std::unique_ptr<Command> operator()(MultiresEditSpec& s) { return multires_edit(s); }
    std::unique_ptr<Command> operator()(SplitTriangleSpec& s) { return split_triangle(s.id, s.at); }
    std::unique_ptr<Command> operator()(ConstructSpec& s) {
        return construct(std::move(s.recipe), std::move(s.name));
    }
    std::unique_ptr<Command> operator()(EditConstructionSpec& s) {
        return edit_construction(s.id, std::move(s.recipe));
    }
    std::unique_ptr<Command> operator()(DetachSpec& s) { return detach(s.id); }
    std::unique_ptr<Command> operator()(MovePointsSpec& s) { return move_points(std::move(s)); }
    std::unique_ptr<Command> operator()(TransformPointsSpec& s) {
        return transform_points(std::move(s));
    }
};

} // namespace

std::unique_ptr<Command> make_command(CommandSpec spec) {
    return std::visit(Build{}, spec);
}

} // namespace isoparm::doc
