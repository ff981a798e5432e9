// The work budget: every costly operation estimates its time and the size of its answer from
// the request alone, before doing any work, and is refused (`limit`, naming what is too large)
// when either is above the budget. docs/protocol.md ("Work budget") has the formulas.
//
// Why: the size caps of the spec (4096 points per direction, 10,000,000 evaluation points)
// still let a 1 KB request ask for hours of work or gigabytes of answer (a degree-4095 curve at
// 10,000 parameters, 10,000,000 parameters with derivatives). The budget is about 10 s of work
// and 1 GiB of memory on a 2-core machine.
#pragma once

#include <string>

#include "core/geom/status.hpp"

namespace isoparm::geom {

// Work is counted in "basis steps": one multiply-add of a basis-function recurrence or of a
// weighted control-point sum. A 2-core machine does about 1e8 per second through the protocol
// (measured: a degree-4095 curve, (p + 1)^2 = 16.8 million steps per parameter, takes 0.15 to
// 0.22 s per parameter), so 1e9 is about 10 s.
inline constexpr double max_work_steps = 1.0e9;
// One instruction of an implicit expression at one grid point costs about 2.5 steps (sin, exp:
// 1,000 terms on a 21^3 grid took 1.2 s).
inline constexpr double steps_per_expression_instruction = 2.5;
// Each number of an answer costs about 5 steps to write: the answers of evaluate, tessellate
// and polygonize are written straight from compact values (stream.hpp), a 1000 x 1000
// tessellation (12 million numbers) in ~0.6 s in all. (Built as a JSON tree, as before issue
// 14, a number cost about 50.)
inline constexpr double steps_per_answer_number = 5;
// The answer is counted in numbers (a coordinate, an index, a null) and capped at 2^24 =
// 16,777,216: 1 GiB had it been a JSON tree (~64 bytes a number while it is built); streamed,
// its compact values take 8 bytes a number and its text ~20, written out 1 MiB at a time.
inline constexpr double max_answer_numbers = 16777216;
inline constexpr double bytes_per_answer_number = 64;

struct WorkEstimate {
    double steps = 0;          // basis steps
    double answer_numbers = 0; // numbers in the answer
};

// The estimates of the costly operations.
// Evaluating a curve of degree p at `count` parameters with derivatives up to d.
WorkEstimate estimate_curve_evaluation(double count, int p, int d);
// Evaluating a surface of degrees (p, q) at `count` parameters, derivatives up to d, normals.
WorkEstimate estimate_surface_evaluation(double count, int p, int q, int d, bool normals);
// Tessellating a surface of degrees (p, q) on an n_u x n_v grid.
WorkEstimate estimate_tessellation(double n_u, double n_v, int p, int q);
// de Casteljau on a degree-n triangle at `count` parameters: about n^3/6 level points of three
// multiply-adds each, once per derivative net ((d+1)(d+2)/2 of them). `all_levels` answers
// every level's points (de_casteljau), else a point and the derivative table per parameter.
WorkEstimate estimate_triangle_de_casteljau(double count, int n, int d, bool all_levels);
// Polygonizing an expression of `instructions` (after folding) on a grid of `grid_points`.
WorkEstimate estimate_polygonization(double grid_points, double instructions);
// Fitting n control points of degree p to `rows` data parameters: the basis at each parameter,
// the banded factorization (p sub- and super-diagonals, widened by pivoting) and the solves for
// `columns` right-hand sides (interpolation, least squares, one direction of a surface).
WorkEstimate estimate_banded_fit(double rows, double n, int p, double columns);

// Checks `cost` against the budget and against what the current batch has left, and charges
// the batch. Refused: `limit` at `path`, the message naming `what` ("12,000,000 parameters of
// a degree-4095 curve") and by how much it is over.
geom::Status spend_work(const WorkEstimate& cost, const std::string& path, const std::string& what);

// While one lives, requests share one budget of `steps` (a batch of eight requests of 8 s each
// stops at the second); without one, each request has the whole budget. Nested inside another,
// it spends from the outer one too (never more than the outer has left).
class BatchBudget {
public:
    explicit BatchBudget(double steps = max_work_steps);
    BatchBudget(const BatchBudget&) = delete;
    BatchBudget& operator=(const BatchBudget&) = delete;
    ~BatchBudget();

private:
    double saved_left_;
    bool saved_active_;
    double start_left_;
};

// "12,000,000" (for messages).
std::string with_thousands(double value);

} // namespace isoparm::geom
