#include "stage/compensate_options.hpp"

#include <cmath>

#include "base/error.hpp"
#include "base/number_text.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

OptionTable<CompensateOptions> make_table() {
  using O = CompensateOptions;
  OptionTable<O> t;
  OptionSpec<O> gain = number_option<O>(
      "gain", "G", "share of the measured error taken off, in (0, 2]: below 1 approaches the correction over several parts",
      [](auto& o) -> auto& { return o.gain; });
  gain.schema["maximum"] = 2;
  const auto read_gain = gain.read;
  gain.read = [read_gain](const nlohmann::json& v, const std::string& where, O& o) {
    read_gain(v, where, o);
    if (o.gain > 2) throw InputError(where + ": must be in (0, 2], got " + shortest(o.gain));
  };
  gain.example = "0.5";
  t.push_back(gain);
  t.push_back(number_option<O>("max_offset", "MM",
                               "largest offset applied to a move; larger ones are clipped to it and listed",
                               [](auto& o) -> auto& { return o.max_offset; }));
  OptionSpec<O> smoothing = parsed_option<O>(
      "smoothing", "MM",
      "smoothing of the error field as a length on the surface (a wave of wavelength 2 pi MM is halved), or auto: "
      "chosen by generalised cross-validation",
      [](auto& o) -> auto& { return o.smoothing; },
      [](const std::string& text, const std::string& where) -> std::optional<double> {
        if (text == "auto") return std::nullopt;
        double v = 0;
        if (!parse_finite(text, v) || !(v > 0))
          throw InputError(where + ": must be a positive length in mm or auto, got '" + text + "'");
        return v;
      },
      [](const std::optional<double>& v) { return v ? shortest(*v) : std::string("auto"); }, {"auto"});
  smoothing.example = "5";
  t.push_back(smoothing);
  OptionSpec<O> clip_back = integer_option<O>(
      "clip_back", "N",
      "rounds of clip-back, in [0, 30]: each halves the offsets of the moves the z-map check finds cutting deeper "
      "than their offset; still unsafe after N rounds: nothing written, exit 3",
      [](auto& o) -> auto& { return o.clip_back; }, 0);
  clip_back.schema["maximum"] = 30;
  const auto read_clip = clip_back.read;
  clip_back.read = [read_clip](const nlohmann::json& v, const std::string& where, O& o) {
    read_clip(v, where, o);
    if (o.clip_back > 30) throw InputError(where + ": must be in [0, 30], got " + std::to_string(o.clip_back));
  };
  clip_back.example = "4";
  t.push_back(clip_back);
  t.push_back(toggle_option<O>(
      "rework",
      "write a rework program instead: only the compensated moves where the field says material is left beyond the "
      "rework threshold, joined by rapids at the program's clearance height (nothing written when there are none)",
      [](auto& o) -> auto& { return o.rework; }));
  t.push_back(default_is(
      number_option<O>("rework_threshold", "MM",
                       "material left [mm] beyond which a move is re-cut (with rework only)",
                       [](auto& o) -> auto& { return o.rework_threshold; }, Bound::non_negative),
      "the upper limit of the comparison's tolerance zone"));
  return t;
}

}  // namespace

const OptionTable<CompensateOptions>& compensate_option_table() {
  static const OptionTable<CompensateOptions> table = make_table();
  return table;
}

}  // namespace furrow
