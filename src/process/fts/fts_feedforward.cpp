#include <stdexcept>

#include "nckit/process/fts/fts_controller.hpp"

namespace nckit {

std::complex<double> discrete_response(const drive::ServoDiscretisation& plant, double rad_per_tick) {
    const auto& phi = plant.transition;
    const auto& gamma = plant.input_gain;
    const std::complex<double> z = std::polar(1.0, rad_per_tick);
    // (z I - Phi)^-1 = adj / det; only the position row of the adjugate is needed.
    const std::complex<double> det = (z - phi[0][0]) * (z - phi[1][1]) - phi[0][1] * phi[1][0];
    const std::complex<double> numerator = (z - phi[1][1]) * gamma[0] + phi[0][1] * gamma[1];
    return numerator / det;
}

ZpetcFeedforward::ZpetcFeedforward(const drive::ServoParameters& model, double period_s) {
    const drive::ServoDiscretisation d = drive::discretise(model, period_s);
    const auto& phi = d.transition;
    const auto& gamma = d.input_gain;
    // Denominator z^2 + a1 z + a2 = det(z I - Phi); numerator b1 z + b2 = c adj(z I - Phi) Gamma.
    const double a1 = -(phi[0][0] + phi[1][1]);
    const double a2 = phi[0][0] * phi[1][1] - phi[0][1] * phi[1][0];
    const double b1 = gamma[0];
    const double b2 = phi[0][1] * gamma[1] - phi[1][1] * gamma[0];
    // b1 = k (1 - Phi00) > 0 and b1 + b2 = k (1 + a1 + a2) > 0 for a stable model with k > 0;
    // anything else is a model no job can describe.
    if (!(b1 > 0.0) || !(b1 + b2 > 0.0)) {
        throw std::invalid_argument("ZPETC needs a model with positive gain");
    }
    beta_ = b2 / b1;
    // u[n] = A(q^-1) (1 + beta q) y[n + 1] / (b1 (1 + beta)^2); with r[n] = y[n+1] + beta y[n+2]
    // that is (r[n] + a1 r[n-1] + a2 r[n-2]) / scale, collected per wanted position.
    const double scale = b1 * (1.0 + beta_) * (1.0 + beta_);
    taps_ = {a2 / scale, (a1 + a2 * beta_) / scale, (1.0 + a1 * beta_) / scale, beta_ / scale};
}

double ZpetcFeedforward::command(std::span<const double, 4> wanted_mm) const {
    // The taps are large (~1 / (w h)^2) and alternate in sign, while their sum is 1 / k: taken
    // about y[n], a profile far from zero (a radius, not a displacement) loses no digits.
    const double centre = wanted_mm[1];
    const double dc = taps_[0] + taps_[1] + taps_[2] + taps_[3];
    return dc * centre + taps_[0] * (wanted_mm[0] - centre) + taps_[2] * (wanted_mm[2] - centre) +
           taps_[3] * (wanted_mm[3] - centre);
}

}  // namespace nckit
