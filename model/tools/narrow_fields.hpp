// SPDX-License-Identifier: Apache-2.0
// The narrowing step shared by the configuration searches (phong_search, device_search): each
// field in turn to the smallest value whose configuration still meets the budget.
#pragma once

#include <vector>

namespace specular {

// One width a search narrows: its name, the member of the format F, its lowest value.
template <class F>
struct SearchField {
  const char* name;
  int F::*member;
  int lo;
};

// Each field, in order, by bisection (the error falls as the width grows) to the smallest value
// whose configuration `meets(F&)` accepts, in passes until none changes. `meets` may adjust the
// configuration it is given (a field another one bounds); the accepted one is kept. `after(field,
// f)` is called once a field is settled.
template <class F, class Meets, class After>
void narrow_fields(F& f, const std::vector<SearchField<F>>& fields, Meets meets, After after) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const SearchField<F>& fd : fields) {
      int hi = f.*(fd.member), lo = fd.lo;
      F keep = f;
      while (lo < hi) {
        const int mid = (lo + hi) / 2;
        F g = f;
        g.*(fd.member) = mid;
        if (meets(g)) {
          hi = mid;
          keep = g;
        } else {
          lo = mid + 1;
        }
      }
      changed = changed || !(keep == f);
      f = keep;
      after(fd, f);
    }
  }
}

}  // namespace specular
