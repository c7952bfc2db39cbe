#pragma once
// The electronic cam as a machine's servo thread runs it: once per servo period it reads the
// spindle encoder (counts and index, or revolutions) and Z, and commands the slaved axis from
// the cam engine (CamTable) with the fast tool servo's feedforward (ZpetcFeedforward) and,
// optionally, learning across revolutions (RepetitiveLearning): the same classes the simulation
// (fast_tool_servo.hpp) uses. Everything that allocates happens in the constructor; step()
// allocates nothing, reads no file and takes no lock, so a realtime thread may call it (the HAL
// component in hal/ does).
#include <cstdint>
#include <optional>

#include "nckit/cam/cam_table.hpp"
#include "nckit/drive/servo_model.hpp"
#include "nckit/process/fts/fts_controller.hpp"
#include "nckit/process/fts/stroke_reference.hpp"

namespace nckit {

//! What may change between ticks (HAL parameters and pins).
struct CamFollowerSettings {
    bool feedforward = false;  //!< command by the model's inverse with two ticks of preview
    bool learning = false;     //!< add learning across revolutions (counts input, forward turning)
    //! Subtract the stroke reference (the middle of the radial range at Z): a fast tool servo
    //! that cuts about the slide's path. Off: the cam value itself (an eccentric's X diameter).
    bool centre = true;
    double scale = 1.0;  //!< the wanted position is scale × (cam − reference)
    //! The controller's model of the axis: k / (T² s² + 2 ζ T s + 1), T = 1 / (2π f_n).
    double model_gain = 1.0;
    double model_natural_frequency_hz = 135.0;
    double model_damping = 0.3;
    double learning_gain = FtsLearning{}.gain;  //!< (0, 2)
    int dac_bits = 0;                           //!< 2 .. 32 quantises the command; 0: no DAC
    double dac_stroke_mm = 1.0;                 //!< the DAC's full scale, centred on 0
    //! |count in turn| an index pulse may be off by and still re-synchronise the turn; further
    //! off, the index is ignored and the index fault is raised.
    int index_tolerance_counts = 2;
};

//! One tick's inputs.
struct CamFollowerInput {
    bool use_counts = true;     //!< counts + index; false: revolutions
    std::int32_t counts = 0;    //!< encoder counts (wraps around like the hardware's)
    bool index = false;         //!< index pulse (the rising edge is the turn's count 0)
    double revolutions = 0.0;   //!< spindle position in turns (revolution input)
    double z_mm = 0.0;          //!< the carriage's position along the table's Z
    double feedback_mm = 0.0;   //!< the slaved axis's measured position (error and learning)
    bool reset_faults = false;  //!< clears the latched index fault
};

//! One tick's outputs.
struct CamFollowerOutput {
    double angle_deg = 0.0;          //!< spindle angle the cam is read at, [0, 360)
    std::int64_t count_in_turn = 0;  //!< counts input: count since the index, [0, counts per rev)
    double cam_mm = 0.0;             //!< the cam table at angle_deg and Z (Z held inside the table)
    double wanted_mm = 0.0;          //!< scale × (cam − reference): where the axis should be now
    double command_mm = 0.0;         //!< what the axis is sent (feedforward, learning, DAC)
    double error_mm = 0.0;           //!< feedback − wanted
    double correction_mm = 0.0;      //!< the learning's share of the command
    double counts_per_tick = 0.0;    //!< the spindle speed estimate
    bool z_fault = false;            //!< Z outside the table (or not finite): the edge row is used
    bool index_fault = false;        //!< an index pulse came at a wrong count (latched until reset)
    bool input_fault = false;        //!< a non-finite revolution or feedback input was held
    bool settings_fault = false;     //!< a model or learning setting was out of range: the last good one is kept
    bool dac_clamped = false;        //!< the command lay beyond the DAC's stroke
    bool learning_active = false;    //!< learning took a count this tick
};

class CamFollower {
public:
    //! `table` (and `reference`, may be null) must outlive this object. `counts_per_rev` >= 8
    //! sets the encoder's counts per turn and the learning's resolution; `period_s` > 0 the servo
    //! period. Allocates the learning's memory. Throws std::invalid_argument for bad arguments.
    CamFollower(const cam::CamTable& table, const StrokeReference* reference, int counts_per_rev, double period_s,
                const CamFollowerSettings& initial = {});

    //! One servo tick. Allocates nothing; throws nothing.
    void step(const CamFollowerInput& in, const CamFollowerSettings& settings, CamFollowerOutput& out);

    //! The servo thread's period, when it differs from the constructor's guess: the feedforward
    //! is re-tuned on the next step. Allocates nothing.
    void set_period(double period_s);

    [[nodiscard]] int counts_per_rev() const { return counts_; }
    [[nodiscard]] double period_s() const { return period_s_; }

    //! Learning harmonics (FtsLearning's default, capped below half the counts per turn).
    [[nodiscard]] int learning_harmonics() const { return harmonics_; }

private:
    //! The wanted position at `position_counts` (any real count) and `z_mm` (held in the table).
    [[nodiscard]] double wanted_at(double position_counts, double z_mm, double scale, bool centre) const;
    void track_counts(const CamFollowerInput& in, const CamFollowerSettings& settings, CamFollowerOutput& out);
    //! Rebuilds the feedforward and the learning's inverse when the model or the speed moved.
    void retune(const CamFollowerSettings& settings, CamFollowerOutput& out);

    const cam::CamTable* table_;
    const StrokeReference* reference_;
    int counts_;
    double period_s_;
    int harmonics_;
    bool has_z_;

    // Spindle tracking.
    bool started_ = false;
    std::int32_t last_counts_ = 0;
    std::int64_t position_ = 0;  //!< counts since start (64 bits: never wraps)
    std::int64_t zero_ = 0;      //!< position of the turn's count 0
    bool synced_ = false;        //!< an index pulse has set zero_
    bool last_index_ = false;
    bool index_fault_ = false;
    double last_position_ = 0.0;  //!< last tick's position in counts (real)
    double speed_ = 0.0;          //!< counts per tick, filtered
    double last_z_mm_ = 0.0;
    double z_speed_ = 0.0;  //!< mm per tick
    double last_command_mm_ = 0.0;
    double last_feedback_mm_ = 0.0;

    // Controller.
    drive::ServoParameters model_{};
    double model_frequency_hz_ = 0.0;
    bool period_changed_ = false;
    double learning_gain_ = 0.0;
    double learning_period_s_ = 0.0;  //!< one count's time the learning's inverse is tuned to
    std::optional<ZpetcFeedforward> feedforward_;
    std::optional<ZpetcFeedforward> count_inverse_;
    std::optional<RepetitiveLearning> learning_;
    std::int64_t learned_to_ = 0;  //!< last position the learning took a count at
    bool learning_on_ = false;
    double correction_mm_ = 0.0;
    bool settings_fault_ = false;
};

}  // namespace nckit
