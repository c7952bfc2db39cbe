#pragma once
// The order of the cuts: which groove next, and which way round, so that the air moves between
// them take little time on the machine. A tour starts and ends at the reference hole. Costs are
// the planner's rest-to-rest rapid times (AirTimer) plus the backlash take-up of every X or Y
// reversal where one motion meets the next. Nearest neighbour builds a tour; 2-opt (reverse a
// run of cuts, which also turns each of them round) and Or-opt (move a run of one to three cuts
// elsewhere, either way round) improve it until no move gains or the work budget is spent.
#include <cstddef>
#include <vector>

#include "nckit/process/pattern/air_motion.hpp"
#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! What the order needs of one cut, as drawn.
struct CutEnds {
    Vec2 start;
    Vec2 end;
    Signs first{0, 0};  //!< each axis's first direction of motion along the cut (0: never moves)
    Signs last{0, 0};   //!< and its last
    std::array<int, 2> internal_reversals{0, 0};  //!< X, Y reversals inside the cut (either way round)
};
//! From the cut's polyline at `deviation_mm` (the polyline the program cuts).
[[nodiscard]] CutEnds describe_cut(const PlaneCurve& curve, double deviation_mm);

struct Tour {
    std::vector<std::size_t> order;  //!< cut indices in cutting order
    std::vector<char> flipped;       //!< per position: cut end to start
};

struct TourCost {
    double air_distance_mm = 0;  //!< XY air moves, from the hole, between cuts and back
    double air_time_s = 0;       //!< their rest-to-rest rapid time
    int reversals = 0;           //!< X and Y reversals over the whole XY motion, cuts included
    double reversal_time_s = 0;  //!< their backlash take-up (or the job's cost per reversal)
    [[nodiscard]] double total_s() const { return air_time_s + reversal_time_s; }
};

struct OrderCosts {
    AirTimer timer;
    std::array<double, 2> reversal_s{0, 0};  //!< cost of one X / Y reversal
    Vec2 home;                               //!< the reference hole
};

[[nodiscard]] Tour drawing_tour(std::size_t cuts);
[[nodiscard]] TourCost evaluate_tour(const std::vector<CutEnds>& cuts, const Tour& tour, const OrderCosts& costs);

//! Nearest neighbour, then 2-opt and Or-opt until a pass gains nothing or `max_evaluations`
//! moves have been tried. Never costlier than drawing order (that order is returned instead).
struct OrderResult {
    Tour tour;
    std::size_t passes = 0;
    std::size_t evaluations = 0;
    bool budget_spent = false;
};
[[nodiscard]] OrderResult optimise_tour(const std::vector<CutEnds>& cuts, const OrderCosts& costs,
                                        std::size_t max_evaluations = 400'000'000);

}  // namespace nckit::pattern
