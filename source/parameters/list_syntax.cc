// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/parameters/list_syntax.h>
#include <dpana/parameters/parameters.h>

#include <cmath>
#include <cstdlib>

namespace dpana
{
  namespace parameters
  {
    namespace
    {
      std::string
      trim(const std::string &s)
      {
        const auto begin = s.find_first_not_of(" \t\r\n");
        if (begin == std::string::npos)
          return "";
        const auto end = s.find_last_not_of(" \t\r\n");
        return s.substr(begin, end - begin + 1);
      }

      std::vector<std::string>
      split(const std::string &s, const std::string &separators)
      {
        std::vector<std::string> parts;
        std::string              current;
        for (const char c : s)
          if (separators.find(c) != std::string::npos)
            {
              parts.push_back(trim(current));
              current.clear();
            }
          else
            current += c;
        parts.push_back(trim(current));
        return parts;
      }

      const char *component_names[3] = {"x", "y", "z"};

      unsigned int
      component_index(const std::string &name,
                      const unsigned int dim,
                      const std::string &parameter)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (name == component_names[d])
            return d;
        throw InputError(parameter + ": unknown displacement component " +
                         quote(name) + " (expected " +
                         (dim == 2 ? "x or y" : "x, y or z") + ")");
      }
    } // namespace



    std::vector<KeyValue>
    split_key_value_list(const std::string &entry, const std::string &parameter)
    {
      std::vector<KeyValue> items;
      for (const std::string &item : split(entry, ";"))
        {
          if (item.empty())
            continue;
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter + ": item " + quote(item) +
                             " has no colon (expected 'name: value')");
          KeyValue kv{trim(item.substr(0, colon)),
                      trim(item.substr(colon + 1))};
          if (kv.key.empty() || kv.value.empty())
            throw InputError(parameter + ": item " + quote(item) +
                             " needs text on both sides of its colon");
          items.push_back(kv);
        }
      return items;
    }



    std::vector<std::string>
    split_names(const std::string &entry, const std::string &parameter)
    {
      (void)parameter;
      std::vector<std::string> names;
      for (const std::string &name : split(entry, ",;"))
        if (!name.empty())
          names.push_back(name);
      return names;
    }



    double
    parse_double(const std::string &text, const std::string &parameter)
    {
      const std::string t = trim(text);
      char             *end;
      const double      value = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0')
        throw InputError(parameter + ": " + quote(t) + " is not a number");
      if (!std::isfinite(value))
        throw InputError(parameter + ": " + quote(t) +
                         " is not a finite number");
      return value;
    }



    std::vector<double>
    parse_doubles(const std::string &text,
                  const unsigned int n,
                  const std::string &parameter)
    {
      const std::vector<std::string> parts = split(text, ",");
      if (parts.size() != n)
        throw InputError(parameter + ": " + quote(trim(text)) + " should be " +
                         std::to_string(n) + " numbers separated by commas");
      std::vector<double> values;
      for (const std::string &p : parts)
        values.push_back(parse_double(p, parameter));
      return values;
    }



    std::vector<bool>
    parse_components(const std::string &text,
                     const unsigned int dim,
                     const std::string &parameter)
    {
      std::vector<bool> mask(dim, false);
      for (const std::string &c : split(text, ","))
        {
          if (c == "all")
            mask.assign(dim, true);
          else
            mask[component_index(c, dim, parameter)] = true;
        }
      return mask;
    }



    std::pair<std::vector<bool>, std::vector<double>>
    parse_component_values(const std::string &text,
                           const unsigned int dim,
                           const std::string &parameter)
    {
      std::vector<bool>   mask(dim, false);
      std::vector<double> values(dim, 0.0);
      for (const std::string &item : split(text, ","))
        {
          const auto equal = item.find('=');
          if (equal == std::string::npos)
            throw InputError(parameter + ": " + quote(item) +
                             " should read 'component = value', e.g. "
                             "'y = -0.1'");
          const unsigned int d =
            component_index(trim(item.substr(0, equal)), dim, parameter);
          mask[d]   = true;
          values[d] = parse_double(item.substr(equal + 1), parameter);
        }
      return {mask, values};
    }
  } // namespace parameters
} // namespace dpana
