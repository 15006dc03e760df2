// tool_vibration.h: a compliant tool's vibration in a cut (a tool on a spring and damper to
// its holder): the steady deflection against the static closed form force / stiffness, and
// the amplitude spectra of the deflection and the forces, whose peak is the tool's mode.
//
// Everything is per unit width, as the cut's forces are: with k and c the mount's stiffness
// and damping per metre of width and m the mass per metre, a deflection d under a force per
// width F obeys m d'' + c d' + k d = F, so the static deflection is F / k and the undamped
// natural frequency f_n = sqrt(k / m) / (2 pi), whatever the width.
//
// The spectra are taken over the engaged part of the cut (from the first series row with a
// force on the tool to the end): the entry excites the mode (a tap test), and the longer the
// record the finer the resolution 1/T. Each is the Hann-windowed discrete Fourier transform
// of the row values minus their mean, evaluated directly at the frequencies of a grid 1/(4 T)
// apart up to the rows' Nyquist frequency, and scaled so that a sinusoid of amplitude A reads
// A at its frequency (sum of the window's weights in the denominator). Rows need not be
// equally spaced (the last row of a run may be closer): each weighs by its share of the time.
// The reported peak is the highest between half and twice the natural frequency: one run's
// spectrum is noisy, and a run-to-run comparison belongs to an ensemble
// (validation/cutting/compliant_tool/).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace swarf {

/// The mount per metre of width, along x (the cutting direction) and z (the thrust direction).
struct ToolMount {
  double stiffness_x = 0;  ///< N/m per m
  double stiffness_z = 0;  ///< N/m per m
  double mass = 0;         ///< kg/m
  double damping = 0;      ///< N s/m per m, the same along x and z
};

/// Series rows of a compliant-tool cut.
struct ToolSeries {
  std::vector<double> time;                        ///< s
  std::vector<double> deflection_x, deflection_z;  ///< the tool's centre minus its holder's anchor, m
  std::vector<double> fc, ft;                      ///< cutting and thrust force per width, N/m
};

struct ToolSpectra {
  std::vector<double> frequency;                   ///< Hz
  std::vector<double> deflection_x, deflection_z;  ///< amplitude, m
  std::vector<double> fc, ft;                      ///< amplitude, N/m
};

struct ToolVibration {
  nlohmann::json summary;  ///< summary.json "tool"
  ToolSpectra spectra;
};

/// Amplitude spectrum of x(t) at the frequencies f (Hz), as described above.
std::vector<double> amplitude_spectrum(const std::vector<double>& t, const std::vector<double>& x,
                                       const std::vector<double>& f);

/// The analysis: statistics over the rows at or after steady_from (s), spectra over the engaged
/// rows.
ToolVibration analyze_tool(const ToolMount& mount, const ToolSeries& s, double steady_from);

/// tool_spectrum.csv: frequency_Hz, the deflections' amplitudes (m) and the forces' (N/m).
std::string tool_spectrum_csv(const ToolSpectra& sp);

}  // namespace swarf
