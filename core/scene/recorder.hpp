// Recording a session as a script (File > Start recording): the commands performed (a drag is
// one step with its final value), undo and redo, and the view changes between them, on the
// scene as it was when the recording started. Replaying the script on that scene gives the
// same document.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/doc/command.hpp"
#include "core/doc/document.hpp"

namespace isoparm::scene {

class Recorder {
public:
    explicit Recorder(const doc::Document& start);

    // Before a command, an undo or a redo, observe() the view as it is then (a point selected
    // in the same frame as its drag began); afterwards say what happened: one step, or the
    // drag's step updated. What the command did to the view replays with it.
    void executed(const doc::History& history, const doc::Document& doc);
    void undone(const doc::Document& doc);
    void redone(const doc::Document& doc);
    // The view as it is now (once a frame): a changed selection, indicator, display or
    // continuity setting becomes a step; consecutive changes of one kind are one step (the
    // indicator dragged across the square is its final position). `camera_degrees` (yaw,
    // pitch), when given, records the 3D view's orbit the same way.
    void observe(const doc::Document& doc,
                 std::optional<std::pair<double, double>> camera_degrees = std::nullopt);

    // Steps the author adds while recording (Lessons > Add stop here: a caption and a pause;
    // Add expectation: an expect): appended as they are. Call observe() first, so the view
    // changes made before them come first.
    void add_steps(const nlohmann::json& steps);
    // The stops added so far (pauses).
    std::size_t stop_count() const;

    std::size_t step_count() const { return steps_.size(); }
    // Commands that have no script form (restoring a recovery file) were left out.
    std::size_t left_out() const { return left_out_; }
    // The script: the starting scene inline and the steps.
    nlohmann::json script() const;

private:
    void append_or_replace(nlohmann::json step, const char* kind);
    void remember_view(const doc::Document& doc);

    nlohmann::json start_;
    nlohmann::json steps_ = nlohmann::json::array();
    std::string last_kind_; // the kind of the last step ("command", "indicator", ...)
    doc::ViewState view_;
    doc::Continuity continuity_ = doc::Continuity::off;
    std::optional<std::pair<double, double>> camera_;
    std::size_t left_out_ = 0;
};

} // namespace isoparm::scene
