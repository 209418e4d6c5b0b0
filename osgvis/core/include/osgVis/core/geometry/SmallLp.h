// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A small dense linear program: maximize c·x subject to A x <= b, equality rows and variable
/// bounds, for a handful of variables (<= 8) and up to a few hundred rows. Dictionary simplex
/// (Chvátal, "Linear Programming", ch. 2-3) with an auxiliary variable for the first phase. Pivots
/// take the largest reduced cost and, among rows nearly tied in the ratio test, the largest pivot
/// (Harris) for accuracy; after a run of degenerate pivots the rules become Bland's, which cannot
/// cycle. Buffers are kept between solves, so a reused solver allocates nothing once warm.
/// Coefficients should be of order one (callers normalise); the pivot tolerance is absolute.
#include <cstddef>
#include <limits>
#include <vector>

namespace osgVis::core
{
class SmallLp
{
public:
    enum class Status
    {
        Optimal,
        Infeasible,
        Unbounded,
        IterationLimit // numerical trouble: callers must treat it as "don't know"
    };
    static constexpr double Infinity = std::numeric_limits<double>::infinity();
    static constexpr int MaxVariables = 8;

    // Starts a new problem with `variableCount` (1..MaxVariables) free variables, no rows and a
    // zero objective.
    void reset(int variableCount);
    // lo may be -Infinity, hi may be +Infinity.
    void setBounds(int variable, double lo, double hi);
    void setObjective(int variable, double coefficient);
    // coefficients has variableCount entries.
    void addLessEqual(const double* coefficients, double rhs);
    void addGreaterEqual(const double* coefficients, double rhs);
    void addEqual(const double* coefficients, double rhs);

    Status maximize();
    // Valid after Optimal.
    double objectiveValue() const { return _value; }
    // After Optimal: an upper bound on the true optimum from the final row duals y >= 0 and the
    // original data alone (c·x = yA·x + (c - yA)·x <= y·b + max over the bounds of (c - yA)·x),
    // so it holds whatever rounding did to the tableau. Callers that decide "infeasible for
    // this threshold" must compare this, not objectiveValue(). +Infinity when no bound follows.
    double upperBound() const { return _upperBound; }
    double solution(int variable) const { return _x[static_cast<std::size_t>(variable)]; }

    int variableCount() const { return _n; }
    std::size_t rowCount() const { return _rowRhs.size(); }

private:
    void pivot(int row, int column);
    // Runs simplex iterations on objective row `objectiveRow`; false when unbounded. Sets
    // _iterationLimitHit when it gives up.
    bool iterate(int objectiveRow, bool allowArtificial);

    // The phases of maximize().
    // Maps each variable to its column(s) y >= 0 and counts the rows its two finite bounds need;
    // false when some lo > hi.
    bool mapVariablesToColumns(int& boundRows);
    // Sizes the tableau (zeroed) and makes the columns nonbasic and the auxiliary the last one.
    void sizeTableau(int boundRows);
    // Writes the rows, the bound rows and the objective row; returns the largest |rhs|.
    double fillTableau();
    // Phase one: Optimal when a feasible basis is in place, else Infeasible or IterationLimit.
    Status findFeasibleBasis(double largestRhs);
    // After phase one: an auxiliary still basic (at zero) leaves the basis.
    void pivotOutAuxiliary();
    // The columns' values into _y, and the variables' values and the objective from them.
    void readSolution();

    int _n = 0;
    double _lo[MaxVariables] = {};
    double _hi[MaxVariables] = {};
    double _c[MaxVariables] = {};
    std::vector<double> _rowCoefficients; // rows of _n entries
    std::vector<double> _rowRhs;

    // Standard form: columns y >= 0; each variable maps to one column (offset + sign * y) or,
    // when free, to two (y+ - y-).
    int _columns = 0;
    int _columnOf[MaxVariables] = {};
    double _sign[MaxVariables] = {};
    double _offset[MaxVariables] = {};
    bool _split[MaxVariables] = {};

    // Tableau: m constraint rows, objective row, phase-one row; columns: nonbasic variables,
    // the auxiliary variable, right-hand side.
    int _m = 0;
    int _width = 0;
    std::vector<double> _t;
    std::vector<int> _basic;    // per row: variable index (columns first, then slacks, -1 auxiliary)
    std::vector<int> _nonbasic; // per column
    std::vector<double> _y;
    bool _iterationLimitHit = false;

    void computeUpperBound();

    double _value = 0.0;
    double _upperBound = Infinity;
    double _x[MaxVariables] = {};
};
} // namespace osgVis::core
