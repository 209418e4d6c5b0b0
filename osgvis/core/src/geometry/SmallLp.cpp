// SPDX-License-Identifier: MIT
#include <osgVis/core/geometry/SmallLp.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace osgVis::core
{
namespace
{
// Pivot elements and reduced costs below this are treated as zero (coefficients are ~1).
constexpr double PivotEpsilon = 1e-9;
constexpr double CostEpsilon = 1e-11;
// Harris' ratio-test slack: rows this close to the minimum ratio compete on pivot size.
constexpr double RatioSlack = 1e-9;
} // namespace

void SmallLp::reset(int variableCount)
{
    assert(variableCount >= 1 && variableCount <= MaxVariables);
    _n = variableCount;
    for (int i = 0; i < _n; ++i)
    {
        _lo[i] = -Infinity;
        _hi[i] = Infinity;
        _c[i] = 0.0;
        _x[i] = 0.0;
    }
    _rowCoefficients.clear();
    _rowRhs.clear();
    _value = 0.0;
}

void SmallLp::setBounds(int variable, double lo, double hi)
{
    _lo[variable] = lo;
    _hi[variable] = hi;
}

void SmallLp::setObjective(int variable, double coefficient)
{
    _c[variable] = coefficient;
}

void SmallLp::addLessEqual(const double* coefficients, double rhs)
{
    _rowCoefficients.insert(_rowCoefficients.end(), coefficients, coefficients + _n);
    _rowRhs.push_back(rhs);
}

void SmallLp::addGreaterEqual(const double* coefficients, double rhs)
{
    for (int i = 0; i < _n; ++i)
        _rowCoefficients.push_back(-coefficients[i]);
    _rowRhs.push_back(-rhs);
}

void SmallLp::addEqual(const double* coefficients, double rhs)
{
    addLessEqual(coefficients, rhs);
    addGreaterEqual(coefficients, rhs);
}

void SmallLp::pivot(int row, int column)
{
    const int rows = _m + 2;
    double* pivotRow = &_t[static_cast<std::size_t>(row) * _width];
    const double inverse = 1.0 / pivotRow[column];
    for (int j = 0; j < _width; ++j)
        if (j != column)
            pivotRow[j] *= inverse;
    pivotRow[column] = inverse;
    for (int i = 0; i < rows; ++i)
    {
        if (i == row)
            continue;
        double* r = &_t[static_cast<std::size_t>(i) * _width];
        const double factor = r[column];
        if (factor == 0.0)
            continue;
        for (int j = 0; j < _width; ++j)
            if (j != column)
                r[j] -= factor * pivotRow[j];
        r[column] = -factor * inverse;
    }
    std::swap(_basic[static_cast<std::size_t>(row)], _nonbasic[static_cast<std::size_t>(column)]);
}

bool SmallLp::iterate(int objectiveRow, bool allowArtificial)
{
    const int auxiliary = _columns + _m;
    const int rhs = _width - 1;
    const int limit = 50 * (_m + _width) + 100;
    const double* objective = &_t[static_cast<std::size_t>(objectiveRow) * _width];
    bool bland = false;
    int degenerate = 0;
    for (int iteration = 0; iteration < limit; ++iteration)
    {
        // Entering: the most improving column, or under Bland the improving one of smallest index.
        int column = -1;
        for (int j = 0; j < rhs; ++j)
        {
            const int variable = _nonbasic[static_cast<std::size_t>(j)];
            if ((!allowArtificial && variable == auxiliary) || !(objective[j] < -CostEpsilon))
                continue;
            if (column < 0 ||
                (bland ? variable < _nonbasic[static_cast<std::size_t>(column)] : objective[j] < objective[column]))
                column = j;
        }
        if (column < 0)
            return true;
        // Leaving: the smallest ratio (rows slightly infeasible from rounding count as zero)...
        auto at = [&](int i, int j) { return _t[static_cast<std::size_t>(i) * _width + j]; };
        double bestRatio = Infinity;
        for (int i = 0; i < _m; ++i)
        {
            const double a = at(i, column);
            if (a > PivotEpsilon)
                bestRatio = std::min(bestRatio, (std::max(0.0, at(i, rhs)) + (bland ? 0.0 : RatioSlack)) / a);
        }
        if (bestRatio == Infinity)
            return false;
        // ...among the rows within Harris' slack of it the largest pivot, or under Bland the
        // exact ties' smallest basic index.
        int row = -1;
        for (int i = 0; i < _m; ++i)
        {
            const double a = at(i, column);
            if (!(a > PivotEpsilon) || std::max(0.0, at(i, rhs)) / a > bestRatio)
                continue;
            if (row < 0 || (bland ? _basic[static_cast<std::size_t>(i)] < _basic[static_cast<std::size_t>(row)]
                                  : a > at(row, column)))
                row = i;
        }
        const double before = objective[rhs];
        pivot(row, column);
        if (objective[rhs] <= before + CostEpsilon && ++degenerate > 2 * _width)
            bland = true;
    }
    _iterationLimitHit = true;
    return true;
}

void SmallLp::computeUpperBound()
{
    // Row duals: the objective row's entries in the columns of nonbasic slacks.
    const std::size_t rows = _rowRhs.size();
    _y.assign(rows, 0.0);
    const double* objective = &_t[static_cast<std::size_t>(_m) * _width];
    for (int j = 0; j + 1 < _width; ++j)
    {
        const int variable = _nonbasic[static_cast<std::size_t>(j)];
        if (variable >= _columns && variable < _columns + static_cast<int>(rows))
            _y[static_cast<std::size_t>(variable - _columns)] = std::max(0.0, objective[j]);
    }
    double bound = 0.0;
    for (std::size_t k = 0; k < rows; ++k)
        bound += _y[k] * _rowRhs[k];
    for (int i = 0; i < _n; ++i)
    {
        double reduced = _c[i];
        double magnitude = std::fabs(_c[i]);
        for (std::size_t k = 0; k < rows; ++k)
        {
            const double term =
                _y[k] * _rowCoefficients[k * static_cast<std::size_t>(_n) + static_cast<std::size_t>(i)];
            reduced -= term;
            magnitude += std::fabs(term);
        }
        // note: against an infinite bound, a reduced cost within rounding of zero counts as zero;
        // with finite bounds (as the portal tests use) the bound stays exact.
        if (!std::isfinite(reduced > 0.0 ? _hi[i] : _lo[i]) && std::fabs(reduced) <= 1e-12 * magnitude)
            continue;
        if (reduced > 0.0)
            bound += reduced * _hi[i]; // +inf when unbounded above
        else if (reduced < 0.0)
            bound += reduced * _lo[i];
    }
    _upperBound = std::isnan(bound) ? Infinity : bound;
}

bool SmallLp::mapVariablesToColumns(int& boundRows)
{
    // Variables to columns y >= 0.
    _columns = 0;
    boundRows = 0;
    for (int i = 0; i < _n; ++i)
    {
        if (_lo[i] > _hi[i])
            return false;
        _columnOf[i] = _columns;
        _split[i] = false;
        if (std::isfinite(_lo[i]))
        {
            _sign[i] = 1.0;
            _offset[i] = _lo[i];
            boundRows += std::isfinite(_hi[i]) ? 1 : 0;
            _columns += 1;
        }
        else if (std::isfinite(_hi[i]))
        {
            _sign[i] = -1.0;
            _offset[i] = _hi[i];
            _columns += 1;
        }
        else
        {
            _sign[i] = 1.0;
            _offset[i] = 0.0;
            _split[i] = true;
            _columns += 2;
        }
    }
    return true;
}

void SmallLp::sizeTableau(int boundRows)
{
    _m = static_cast<int>(_rowRhs.size()) + boundRows;
    _width = _columns + 2;
    const int auxiliaryColumn = _columns;
    _t.assign(static_cast<std::size_t>(_m + 2) * _width, 0.0);
    _basic.resize(static_cast<std::size_t>(_m));
    _nonbasic.resize(static_cast<std::size_t>(_columns + 1));
    for (int j = 0; j < _columns; ++j)
        _nonbasic[static_cast<std::size_t>(j)] = j;
    _nonbasic[static_cast<std::size_t>(auxiliaryColumn)] = _columns + _m;
}

double SmallLp::fillTableau()
{
    const int auxiliaryColumn = _columns;
    const int rhs = _columns + 1;
    double largestRhs = 0.0;
    auto fillRow = [&](int row, const double* a, double b)
    {
        double* r = &_t[static_cast<std::size_t>(row) * _width];
        for (int i = 0; i < _n; ++i)
        {
            if (a[i] == 0.0)
                continue;
            b -= a[i] * _offset[i];
            r[_columnOf[i]] += a[i] * _sign[i];
            if (_split[i])
                r[_columnOf[i] + 1] -= a[i];
        }
        r[auxiliaryColumn] = -1.0;
        r[rhs] = b;
        largestRhs = std::max(largestRhs, std::fabs(b));
        _basic[static_cast<std::size_t>(row)] = _columns + row;
    };
    int row = 0;
    for (std::size_t k = 0; k < _rowRhs.size(); ++k, ++row)
        fillRow(row, &_rowCoefficients[k * static_cast<std::size_t>(_n)], _rowRhs[k]);
    for (int i = 0; i < _n; ++i)
    {
        if (!std::isfinite(_lo[i]) || !std::isfinite(_hi[i]))
            continue;
        double* r = &_t[static_cast<std::size_t>(row) * _width];
        r[_columnOf[i]] = 1.0;
        r[auxiliaryColumn] = -1.0;
        r[rhs] = _hi[i] - _lo[i];
        _basic[static_cast<std::size_t>(row)] = _columns + row;
        ++row;
    }
    double* objective = &_t[static_cast<std::size_t>(_m) * _width];
    for (int i = 0; i < _n; ++i)
    {
        objective[_columnOf[i]] -= _c[i] * _sign[i];
        if (_split[i])
            objective[_columnOf[i] + 1] += _c[i];
    }
    return largestRhs;
}

SmallLp::Status SmallLp::findFeasibleBasis(double largestRhs)
{
    const int auxiliaryColumn = _columns;
    const int rhs = _columns + 1;
    // Phase one (only when the origin of the y space is infeasible): maximize -auxiliary after
    // one pivot that makes every row feasible.
    int worst = -1;
    for (int i = 0; i < _m; ++i)
        if (_t[static_cast<std::size_t>(i) * _width + rhs] < 0.0 &&
            (worst < 0 ||
             _t[static_cast<std::size_t>(i) * _width + rhs] < _t[static_cast<std::size_t>(worst) * _width + rhs]))
            worst = i;
    if (worst < 0)
        return Status::Optimal;
    _t[static_cast<std::size_t>(_m + 1) * _width + auxiliaryColumn] = 1.0;
    pivot(worst, auxiliaryColumn);
    iterate(_m + 1, true);
    if (_iterationLimitHit)
        return Status::IterationLimit;
    if (_t[static_cast<std::size_t>(_m + 1) * _width + rhs] < -1e-9 * (1.0 + largestRhs))
        return Status::Infeasible;
    pivotOutAuxiliary();
    return Status::Optimal;
}

void SmallLp::pivotOutAuxiliary()
{
    const int rhs = _columns + 1;
    // A basic auxiliary (at zero) leaves through its largest coefficient.
    const int auxiliary = _columns + _m;
    for (int i = 0; i < _m; ++i)
    {
        if (_basic[static_cast<std::size_t>(i)] != auxiliary)
            continue;
        int best = -1;
        for (int j = 0; j < rhs; ++j)
            if (best < 0 || std::fabs(_t[static_cast<std::size_t>(i) * _width + j]) >
                                std::fabs(_t[static_cast<std::size_t>(i) * _width + best]))
                best = j;
        if (best >= 0 && std::fabs(_t[static_cast<std::size_t>(i) * _width + best]) > PivotEpsilon)
            pivot(i, best);
    }
}

void SmallLp::readSolution()
{
    const int rhs = _columns + 1;
    _y.assign(static_cast<std::size_t>(_columns), 0.0);
    for (int i = 0; i < _m; ++i)
        if (_basic[static_cast<std::size_t>(i)] < _columns)
            _y[static_cast<std::size_t>(_basic[static_cast<std::size_t>(i)])] =
                std::max(0.0, _t[static_cast<std::size_t>(i) * _width + rhs]);
    // note: _y holds the columns' values here, the row duals after computeUpperBound().
    _value = 0.0;
    for (int i = 0; i < _n; ++i)
    {
        const double y = _y[static_cast<std::size_t>(_columnOf[i])];
        _x[i] = _split[i] ? y - _y[static_cast<std::size_t>(_columnOf[i] + 1)] : _offset[i] + _sign[i] * y;
        _value += _c[i] * _x[i];
    }
}

SmallLp::Status SmallLp::maximize()
{
    _iterationLimitHit = false;
    _upperBound = Infinity;
    int boundRows = 0;
    if (!mapVariablesToColumns(boundRows))
        return Status::Infeasible;
    sizeTableau(boundRows);
    const double largestRhs = fillTableau();

    const Status phaseOne = findFeasibleBasis(largestRhs);
    if (phaseOne != Status::Optimal)
        return phaseOne;

    const bool bounded = iterate(_m, false);
    if (_iterationLimitHit)
        return Status::IterationLimit;
    if (!bounded)
        return Status::Unbounded;

    readSolution();
    computeUpperBound();
    return Status::Optimal;
}
} // namespace osgVis::core
