// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_parameters_list_syntax_h
#define dpana_parameters_list_syntax_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <utility>
#include <vector>

namespace dpana
{
  namespace parameters
  {
    /**
     * The syntax of list-valued entries (documented in doc/parameters.md).
     *
     * Many entries attach something to several boundaries at once:
     *
     *     set Fixed    = bottom: x, y; left: x
     *     set Pressure = top: 50; right: 100
     *
     * An entry is a list of items separated by semicolons; each item is a
     * KEY, a colon and a VALUE. Blank items are ignored, so that an empty
     * entry is an empty list. All functions throw dpana::InputError with a
     * one-line message that starts with @p parameter, the path of the entry
     * (e.g. "Body 1 / Boundary conditions / Fixed").
     */
    struct KeyValue
    {
      std::string key;
      std::string value;
    };

    /**
     * Split "key: value; key: value" into its items. Keys and values are
     * trimmed; neither may be empty.
     */
    std::vector<KeyValue>
    split_key_value_list(const std::string &entry,
                         const std::string &parameter);

    /**
     * Split a list of names separated by commas or semicolons.
     */
    std::vector<std::string>
    split_names(const std::string &entry, const std::string &parameter);

    /**
     * Parse one finite real number.
     */
    double
    parse_double(const std::string &text, const std::string &parameter);

    /**
     * Parse exactly @p n finite real numbers separated by commas.
     */
    std::vector<double>
    parse_doubles(const std::string &text,
                  const unsigned int n,
                  const std::string &parameter);

    /**
     * Parse a list of displacement components "x, y" (or "all") into a mask
     * of @p dim flags; "z" is accepted only in 3D.
     */
    std::vector<bool>
    parse_components(const std::string &text,
                     const unsigned int dim,
                     const std::string &parameter);

    /**
     * Parse "x = 0.1, y = -0.2": a value for some displacement components.
     * Returns (mask, values), values of unlisted components being zero.
     */
    std::pair<std::vector<bool>, std::vector<double>>
    parse_component_values(const std::string &text,
                           const unsigned int dim,
                           const std::string &parameter);

    /**
     * Parse a point of @p dim finite coordinates "x, y(, z)" (mm). The one
     * parser of points and vectors of every component: a NaN, an infinity,
     * a missing or an extra coordinate is refused with a one-line message
     * naming @p parameter.
     */
    template <int dim>
    dealii::Point<dim>
    parse_point(const std::string &text, const std::string &parameter)
    {
      const std::vector<double> x = parse_doubles(text, dim, parameter);
      dealii::Point<dim>        p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      return p;
    }

    /**
     * Parse a vector of @p dim finite components, as parse_point().
     */
    template <int dim>
    dealii::Tensor<1, dim>
    parse_vector(const std::string &text, const std::string &parameter)
    {
      return parse_point<dim>(text, parameter);
    }
  } // namespace parameters
} // namespace dpana

#endif
