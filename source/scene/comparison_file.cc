// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The reference "Comparison file": the tractions of an earlier run (its
// contact.csv, columns s, N, T) read once, and this run's tractions compared
// with them.
#include <dpana/base/exceptions.h>
#include <dpana/io/csv.h>
#include <dpana/scene/references.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace dpana
{
  namespace scene
  {
    template <int dim>
    void
    References<dim>::load_comparison_file()
    {
      comparison_table.clear();
      if (comparison_file.empty())
        return;
      const std::string what =
        "Contact / Reference / Comparison file '" + comparison_file + "'";
      if (!std::filesystem::exists(comparison_file))
        {
          warn(what + " not found (run the scene that writes it first); no "
                      "comparison is printed");
          return;
        }
      if (std::filesystem::is_directory(comparison_file))
        throw InputError(what + " is a directory, not a file");
      const io::CsvTable table = io::read_csv(comparison_file, what);
      const int          cs    = table.column({"s"});
      const int          cN    = table.column({"N"});
      const int          cT    = table.column({"T", "T1"});
      if (cs < 0 || cN < 0 || cT < 0)
        throw InputError(what + " has no columns s, N, T");
      for (unsigned int i = 0; i < table.rows.size(); ++i)
        comparison_table.push_back({{table.number(i, cs, what),
                                     table.number(i, cN, what),
                                     table.number(i, cT, what)}});
      if (comparison_table.size() < 2)
        throw InputError(what + " has fewer than two rows");
      std::sort(comparison_table.begin(), comparison_table.end());
    }



    // N and T of the comparison run interpolated linearly in s at the
    // centroids of this run's elements (in 3D those of the first row, t
    // minimal: the symmetry plane).
    template <int dim>
    Comparison
    References<dim>::comparison_run(
      const contact_surface::ContactSurface<dim> &surface,
      const ContactSummary                       &summary) const
    {
      const auto &ref    = comparison_table;
      const auto  interp = [&](const double s, const unsigned int c) {
        if (s <= ref.front()[0])
          return ref.front()[c];
        if (s >= ref.back()[0])
          return ref.back()[c];
        auto        it = std::lower_bound(ref.begin(),
                                   ref.end(),
                                   std::array<double, 3>{{s, -1e300, -1e300}});
        const auto &b = *it, &a = *(it - 1);
        return a[c] + (b[c] - a[c]) * (s - a[0]) / (b[0] - a[0]);
      };
      double tmin = std::numeric_limits<double>::max();
      for (const auto &e : surface.get_elements())
        tmin = std::min(tmin, e.t_min);
      double eN = 0, eT = 0, scale = 0;
      for (const auto &r : ref)
        scale = std::max(scale, std::abs(r[1]));
      const auto &r = summary.result.r;
      for (unsigned int j = 0; j < summary.n_elements; ++j)
        {
          const auto &e = surface.element(j);
          if (dim == 3 && e.t_min > tmin + 1e-10 * (1 + std::abs(tmin)))
            continue;
          eN = std::max(eN, std::abs(r(dim * j) - interp(e.s, 1)));
          eT = std::max(eT, std::abs(r(dim * j + 1) - interp(e.s, 2)));
        }
      std::ostringstream out;
      out << std::setprecision(6) << "Reference (" << comparison_file
          << "): max |N - N_ref| / max|N_ref| = " << eN / scale
          << ", max |T - T_ref| / max|N_ref| = " << eT / scale;
      return {"comparison file",
              out.str(),
              {{"max_N_difference", eN / scale},
               {"max_T_difference", eT / scale}},
              comparison_file};
    }



    template void
    References<2>::load_comparison_file();
    template void
    References<3>::load_comparison_file();
    template Comparison
    References<2>::comparison_run(const contact_surface::ContactSurface<2> &,
                                  const ContactSummary &) const;
    template Comparison
    References<3>::comparison_run(const contact_surface::ContactSurface<3> &,
                                  const ContactSummary &) const;
  } // namespace scene
} // namespace dpana
