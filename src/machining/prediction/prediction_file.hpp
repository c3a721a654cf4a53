#pragma once
// prediction.json: the machining-error prediction written by `furrow
// predict` and read by every later stage (docs/formats.md "prediction.json").
// Other modules read predictions only through read_prediction() and
// Prediction::predicted_error_at() (prediction.hpp).
//
// Writer in prediction_file.cpp, reader in prediction_reader.cpp. The
// writer is deterministic (json_fields::to_text; error values and
// coordinates rounded to 1e-7 mm, parameters to 1e-12), never writes NaN or
// infinity, and marks cells without a prediction by their status letter with
// null values. The reader validates everything and throws InputError naming
// the file and the field ("prediction.json: faces[0].mean[17]: expected a
// number for a reached cell, got null").
#include <string>

#include "machining/prediction/prediction.hpp"

namespace furrow {

constexpr int kPredictionFormatVersion = 1;

std::string prediction_to_json_text(const Prediction& prediction);
void write_prediction(const Prediction& prediction, const std::string& path);

Prediction parse_prediction_json(const std::string& text, const std::string& name);
Prediction read_prediction(const std::string& path);

// One letter per cell status in the file: R reached, N not reached, O
// outside the face (trimmed), M not machinable.
char status_letter(ErrorCellStatus status);

}  // namespace furrow
