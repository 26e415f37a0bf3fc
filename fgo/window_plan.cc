// The window's symbolic plan: its variables' order, the factors' layouts, H's sparsity pattern
// and CHOLMOD's analysis, made once per window shape (fgo/window_linearization.h).
#include <map>

#include "fgo/window_linearization.h"

namespace giocal {

std::shared_ptr<SlidingWindow::WindowPlan> SlidingWindow::plan() const {
  auto p = std::make_shared<WindowPlan>();
  p->structure = structure_;
  const std::vector<StateKey> order = estimatedVariables();
  p->offset = tangentOffsets(order, &p->n);
  for (const StateKey& name : order) {
    for (int c : vars_.at(name).held) p->held.push_back(p->offset.at(name) + c);
  }
  std::vector<const Factor*> all;
  for (const Factor& fac : factors_) all.push_back(&fac);
  p->layouts = layouts(p->offset, all);
  // A window that slid by one epoch usually has the shape of the last: the same blocks at the
  // same offsets, the same held indices and every factor on the same segments. Then H's pattern,
  // the scatter indices and CHOLMOD's ordering (the same pattern gives the same one) are reused:
  // the symbolic work was about a seventh of the factor graph's time.
  std::vector<int> shape{p->n, static_cast<int>(order.size())};
  for (const StateKey& name : order) {
    shape.push_back(p->offset.at(name));
    shape.push_back(vars_.at(name).block.tangentSize());
  }
  shape.push_back(static_cast<int>(p->held.size()));
  shape.insert(shape.end(), p->held.begin(), p->held.end());
  for (const FactorLayout& l : p->layouts) {
    shape.push_back(static_cast<int>(l.segments.size()));
    for (const Segment& v : l.segments) shape.insert(shape.end(), {v.global, v.local, v.size});
  }
  if (plan_ && plan_->symbolic && plan_->symbolic->shape == shape) {
    p->symbolic = plan_->symbolic;
    return p;
  }
  p->symbolic = std::make_shared<SymbolicPlan>();
  ++symbolic_analyses_;
  SymbolicPlan& sp = *p->symbolic;
  sp.shape = std::move(shape);
  // The window's Hessian is sparse (a chain of epochs plus the calibration and ambiguity columns):
  // a sparse factorization is ~10x cheaper than a dense one at window 30, and CHOLMOD's ordering
  // ~15x cheaper than Eigen's own AMD (measured, docs/results.md). Its lower triangle's pattern is
  // built block by block: per variable (a column block), the variables at or after it that share
  // a factor with it (row blocks, its own first).
  const int n = p->n;
  std::vector<int> block_of(static_cast<size_t>(n), -1), start, size;
  for (const StateKey& name : order) {
    block_of[static_cast<size_t>(p->offset.at(name))] = static_cast<int>(start.size());
    start.push_back(p->offset.at(name));
    size.push_back(vars_.at(name).block.tangentSize());
  }
  // The factors on each variable; then per variable its distinct neighbours at or after it
  // (marked once each rather than collected with repeats and sorted).
  std::vector<std::vector<const FactorLayout*>> on(start.size());
  for (const FactorLayout& l : p->layouts) {
    for (const Segment& v : l.segments) on[static_cast<size_t>(block_of[v.global])].push_back(&l);
  }
  std::vector<std::vector<int>> below(start.size());  // row-block starts per column block
  std::vector<int> marked(start.size(), -1);
  for (size_t c = 0; c < start.size(); ++c) {
    for (const FactorLayout* l : on[c]) {
      for (const Segment& u : l->segments) {
        const int r = block_of[u.global];
        if (u.global < start[c] || marked[static_cast<size_t>(r)] == static_cast<int>(c)) continue;
        marked[static_cast<size_t>(r)] = static_cast<int>(c);
        below[c].push_back(u.global);
      }
    }
  }
  std::vector<std::vector<int>> rows_before(start.size());  // per row block, in a column below
  std::vector<int> outer(static_cast<size_t>(n) + 1, 0), inner;
  for (size_t c = 0; c < start.size(); ++c) {
    std::vector<int>& rows = below[c];
    std::sort(rows.begin(), rows.end());
    int before = 0;
    for (int r : rows) {
      rows_before[c].push_back(before);
      if (r != start[c]) before += size[static_cast<size_t>(block_of[r])];
    }
    for (int j = 0; j < size[c]; ++j) {
      outer[static_cast<size_t>(start[c] + j)] = static_cast<int>(inner.size());
      for (int r : rows) {
        const int first = r == start[c] ? r + j : r;
        for (int i = first; i < r + size[static_cast<size_t>(block_of[r])]; ++i) inner.push_back(i);
      }
    }
  }
  outer[static_cast<size_t>(n)] = static_cast<int>(inner.size());
  const std::vector<double> zeros(inner.size(), 0.0);
  sp.pattern = Eigen::Map<const Eigen::SparseMatrix<double>>(
      n, n, static_cast<long>(inner.size()), outer.data(), inner.data(), zeros.data());
  // Each entry of a factor's J^T J in H's lower triangle: where it goes (dest) and where it is in
  // the factor's own lower-triangular Hf (src), read per linearization as value[dest] += Hf[src].
  for (const FactorLayout& l : p->layouts) {
    std::vector<int>& d = sp.dest.emplace_back();
    std::vector<int>& from = sp.src.emplace_back();
    d.reserve(static_cast<size_t>(l.cols * (l.cols + 1) / 2));
    from.reserve(d.capacity());
    for (const Segment& u : l.segments) {
      for (const Segment& v : l.segments) {
        if (v.global > u.global) continue;
        const size_t c = static_cast<size_t>(block_of[v.global]);
        const std::vector<int>& rows = below[c];
        const size_t at = static_cast<size_t>(std::lower_bound(rows.begin(), rows.end(), u.global) -
                                              rows.begin());
        for (int j = 0; j < v.size; ++j) {
          const int col = v.global + j;
          // Column j of a diagonal block starts at its row j; an off-diagonal block's rows follow
          // the diagonal block's remaining rows and the blocks before it.
          const int base = u.global == v.global ? outer[static_cast<size_t>(col)] - j
                                                : outer[static_cast<size_t>(col)] + (v.size - j) +
                                                      rows_before[c][at];
          for (int i = u.global == v.global ? j : 0; i < u.size; ++i) {
            d.push_back(base + i);
            const int r = u.local + i, q = v.local + j;  // local row and column
            from.push_back(r >= q ? q * l.cols + r : r * l.cols + q);
          }
        }
      }
    }
  }
  sp.llt.cholmod().print = 0;  // a singular H is handled by the callers, not printed
  sp.llt.analyzePattern(sp.pattern);
  return p;
}

}  // namespace giocal
