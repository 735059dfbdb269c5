// "Simplification Report": compares the current layer with its original (core/
// simplification_report.h), logs distances and compactness with a histogram, and can paint
// the distance as vertex quality and the compactness as face quality.
#pragma once

#include <common/interfaces.h>

namespace cadlod {

void reportParameters(MeshDocument& md, RichParameterList& par);
bool simplificationReport(MeshFilterInterface& plugin, MeshDocument& md, const RichParameterList& par,
                          QString& error);

}  // namespace cadlod
