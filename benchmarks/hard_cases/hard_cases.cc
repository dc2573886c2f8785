// The hard-case matrix of dpana's contact solvers: every cell of
// problems.h (and any FCLIB file given with --fclib, e.g. the condensed
// problems of whole runs) solved by every solver; per cell whether it
// converged, its iterations, time, residual and, where a reference answer
// is known, its error. Every cell must either converge to the tolerance or
// stop with a message that names the cause.
//
//   hard_cases [--quick] [--csv FILE] [--fclib FILE...]
//
// Prints the matrix and the fraction converged per solver as Markdown
// tables. With --quick (the ctest) it solves a subset and exits with
// status 1 if the default solver fails a cell or a solver stops without
// naming the cause.
#include <dpana/contact/solver.h>
#include <dpana/io/fclib.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "problems.h"

namespace
{
  using namespace dpana;
  using contact::SolverOptions;
  using contact::SolverResult;
  using contact::SolverType;

  // The solvers of the matrix: the default (the splitting with its
  // fallback), and each solver alone.
  struct Column
  {
    std::string   name;
    SolverOptions options;
  };

  std::vector<Column>
  columns()
  {
    std::vector<Column> list;
    SolverOptions       o;
    list.push_back({"default", o});
    o.fallback = false;
    for (const SolverType type : {SolverType::splitting_active_set,
                                  SolverType::splitting_pgs,
                                  SolverType::nsgs,
                                  SolverType::alart_curnier})
      {
        o.type = type;
        list.push_back({contact::to_string(type), o});
      }
    return list;
  }

  struct Outcome
  {
    SolverResult result;
    double       seconds = 0;
    double       error   = -1; // relative to the reference, -1: unknown
  };

  Outcome
  run(const contact::ContactProblem &problem, const SolverOptions &options)
  {
    Outcome    o;
    const auto start = std::chrono::steady_clock::now();
    o.result         = contact::solve(problem, options);
    o.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    return o;
  }

  // The reference answer: Alart-Curnier, then NSGS, to 1e-13 (a tighter
  // tolerance than the matrix's 1e-10), or none.
  const SolverResult *
  reference(const contact::ContactProblem &problem, SolverResult &storage)
  {
    for (const SolverType type : {SolverType::alart_curnier, SolverType::nsgs})
      {
        SolverOptions o;
        o.type           = type;
        o.tolerance      = 1e-13;
        o.max_iterations = 5000;
        storage          = contact::solve(problem, o);
        if (storage.converged)
          return &storage;
      }
    return nullptr;
  }

  std::string
  format(const char *pattern, const double x)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), pattern, x);
    return buffer;
  }

  // One cell of the Markdown table.
  std::string
  cell(const Outcome &o)
  {
    const SolverResult &r = o.result;
    std::string         text =
      (r.converged ? "yes " : "**no** ") + std::to_string(r.iterations) + ", " +
      format("%.2g s", o.seconds) + ", " + format("%.1e", r.residual);
    if (o.error >= 0)
      text += ", err " + format("%.0e", o.error);
    if (!r.fallbacks.empty() && r.converged)
      text += " (" + contact::to_string(r.solver) + ")";
    if (!r.converged)
      text += ": " + r.message;
    return text;
  }

  // The stop message names a cause: converged, or one of the messages of
  // the monitor and the solvers (monitor.h), which all say what happened.
  bool
  names_cause(const SolverResult &r)
  {
    if (r.converged)
      return true;
    for (const char *cause : {"did not converge",
                              "iteration limit",
                              "diverged",
                              "stagnated",
                              "line search",
                              "singular",
                              "no solver converged"})
      if (r.message.find(cause) != std::string::npos)
        return true;
    return false;
  }
} // namespace



int
main(int argc, char **argv)
{
  bool                     quick = false;
  std::string              csv_name;
  std::vector<std::string> fclib;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--quick")
        quick = true;
      else if (arg == "--csv" && i + 1 < argc)
        csv_name = argv[++i];
      else if (arg == "--fclib")
        while (i + 1 < argc && argv[i + 1][0] != '-')
          fclib.push_back(argv[++i]);
      else
        {
          std::cerr << "hard_cases: error: unknown argument '" << arg
                    << "' (expected --quick, --csv FILE, --fclib FILE...)\n";
          return 1;
        }
    }

  std::vector<benchmarks::HardCase> cases = benchmarks::hard_cases(quick);
  for (const std::string &file : fclib)
    {
      // The name of the run: the folder of its problem.hdf5.
      std::string name = file.substr(0, file.find_last_of('/'));
      name             = name.substr(name.find_last_of('/') + 1);
      cases.push_back({"whole run", name, io::read_fclib_local(file)});
    }

  const std::vector<Column> solvers = columns();
  std::ofstream             csv;
  if (!csv_name.empty())
    {
      csv.open(csv_name);
      csv << "family,case,unknowns,solver,converged,iterations,seconds,"
             "residual,error,solved_by,message\n";
    }
  std::cout << "| family | case | n | ";
  for (const Column &c : solvers)
    std::cout << c.name << " | ";
  std::cout << "\n|---|---|---|";
  for (std::size_t i = 0; i < solvers.size(); ++i)
    std::cout << "---|";
  std::cout << '\n';

  std::map<std::string, std::pair<unsigned int, unsigned int>> converged;
  bool                                                         ok = true;
  for (const benchmarks::HardCase &c : cases)
    {
      SolverResult        storage;
      const SolverResult *ref = reference(c.problem, storage);
      std::cout << "| " << c.family << " | " << c.name << " | "
                << c.problem.n_elements() << " | ";
      for (const Column &column : solvers)
        {
          Outcome o = run(c.problem, column.options);
          if (ref && ref->r.norm() > 0)
            o.error = (o.result.r - ref->r).norm() / ref->r.norm();
          std::cout << cell(o) << " | " << std::flush;
          auto &count = converged[column.name];
          count.first += o.result.converged ? 1 : 0;
          count.second += 1;
          if (!names_cause(o.result) ||
              (column.name == "default" && !o.result.converged))
            ok = false;
          if (csv.is_open())
            csv << '"' << c.family << "\",\"" << c.name << "\","
                << c.problem.D.size() << ',' << column.name << ','
                << o.result.converged << ',' << o.result.iterations << ','
                << o.seconds << ',' << o.result.residual << ',' << o.error
                << ',' << contact::to_string(o.result.solver) << ",\""
                << o.result.message << "\"\n";
        }
      std::cout << '\n';
    }

  std::cout << "\n| solver | converged |\n|---|---|\n";
  for (const Column &column : solvers)
    {
      const auto &count = converged[column.name];
      std::cout << "| " << column.name << " | " << count.first << " / "
                << count.second << " ("
                << format("%.0f", 100.0 * count.first / count.second)
                << " %) |\n";
    }
  if (quick && !ok)
    {
      std::cerr << "hard_cases: error: the default solver failed a cell, or "
                   "a solver stopped without naming the cause\n";
      return 1;
    }
  return 0;
}
