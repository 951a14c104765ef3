// The records of a continuation's journal (continuation_command.hpp; the file itself is a
// PointJournal, point_journal.hpp, like the sweep's): one accepted point of the trim branch as one
// line of text holding every number exactly, so that a resumed run continues from the same bits
// and writes the same bytes as an uninterrupted one.
//
// Payload: the event ("-" for a regular point), then the point's scalars (index, parameter,
// arclength, residual, corrector iterations, max |mu|, stable, tangent and step, friction speeds,
// CG shift, the operating point, the cycle means) as " %.17g" numbers, then the orbit's vectors
// (state, parameters, unknowns, tangent, grid origin: each its length and its values), the
// multipliers (count, then real and imaginary parts), and " |" followed by the leading
// multiplier's label (which may hold spaces).
#pragma once

#include <string>
#include <string_view>

#include "trim/trim_continuation.hpp"

namespace orni::studies {

/// The payload of `point`.
std::string encodeContinuationPoint(const TrimContinuationPoint& point);

/// Inverse of encodeContinuationPoint; false when the payload is malformed or its sizes disagree
/// (an orbit without states, a tangent or grid origin of another length than the unknowns).
bool decodeContinuationPoint(std::string_view payload, TrimContinuationPoint* point);

}  // namespace orni::studies
