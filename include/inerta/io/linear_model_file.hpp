#pragma once
// The linear model of `inerta modes --export FILE` (docs/cli.md), for MATLAB/Python: about the
// static equilibrium q_e, Ẋ = A X with X = [ξ; ξ̇; z] and q = q_e + N ξ (spec/02 §2.5), and the
// reduced M, C, K (mbs::linearise). JSON (io/json.hpp), keys in this order:
//   model, state (the text above), coordinates (names of q), dof, internal_states,
//   q_e (one row), N, A, M, C, K (lists of rows; SI units).
#include <string>

#include "inerta/io/json.hpp"
#include "inerta/mbs/linearisation.hpp"
#include "inerta/mbs/model.hpp"

namespace inerta::io {

/// The document for the linearisation `lin` of `model` (q_e = lin.equilibrium.q).
Json linear_model_json(const mbs::Model& model, const mbs::LinearModel& lin);

/// Writes linear_model_json to `path` (std::runtime_error "cannot write 'path'" on failure).
void write_linear_model(const std::string& path, const mbs::Model& model, const mbs::LinearModel& lin);

}  // namespace inerta::io
