// What the option table says of the form-factor methods, read from their registrations
// (radiosity/form_factor_methods.h) so that no consumer names a method by hand: when the result
// file records --form-factors (every method but the paper's) and each method's own options (its
// runs only), and each method's rules under --form-factors' "methods" (defined with V > 0 or
// why not, whether it traces rays, its own options), which the sweep's validation reads from
// --describe-options (analysis/ncube/options.py).
#pragma once

#include "tools/option_table.h"

namespace ncube {

// After the methods' own options are in `table`; std::logic_error for an own option that is
// not (a registration naming a field no option records).
void annotate_form_factor_methods(OptionTable& table);

}  // namespace ncube
