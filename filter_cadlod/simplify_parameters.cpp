#include "simplify_parameters.h"

#include "simplify/parameter_table.h"

namespace cadlod {
namespace {

void addParameter(RichParameterList& par, const SimplifyParameter& row)
{
    const double value = defaultOf(row);
    switch (row.field.kind) {
    case ParameterKind::Bool:
        par.addParam(RichBool(row.name, value != 0, row.label, row.help));
        break;
    case ParameterKind::Int:
        par.addParam(RichInt(row.name, int(value), row.label, row.help));
        break;
    case ParameterKind::Float:
        par.addParam(RichFloat(row.name, float(value), row.label, row.help));
        break;
    }
}

double valueIn(const RichParameterList& par, const SimplifyParameter& row)
{
    switch (row.field.kind) {
    case ParameterKind::Bool:
        return par.getBool(row.name) ? 1.0 : 0.0;
    case ParameterKind::Int:
        return par.getInt(row.name);
    case ParameterKind::Float:
        break;
    }
    return par.getFloat(row.name);
}

}  // namespace

void addFeatureParameters(RichParameterList& par)
{
    for (const SimplifyParameter& row : kSimplifyParameters)
        if (row.inLodSetFilter)
            addParameter(par, row);
}

void addPlacementParameters(RichParameterList& par)
{
    for (const SimplifyParameter& row : kSimplifyParameters)
        addParameter(par, row);
}

void readPlacementParameters(const RichParameterList& par, SimplifyParams& p)
{
    for (const SimplifyParameter& row : kSimplifyParameters)
        if (par.hasParameter(row.name))
            row.field.set(p, valueIn(par, row));
}

}  // namespace cadlod
