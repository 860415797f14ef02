// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_io_parameter_file_h
#define fluid_surface_io_parameter_file_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/tensor.h>

#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * Bad user input: a parameter file, an entry or a mesh that cannot be used.
   * The message names the file, the line or entry, and what was expected;
   * main() prints it on stderr and exits with status 2 before any computation.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The pattern of every real-valued entry: a finite number in an interval whose ends are open or closed
   * (an infinite end is open). Unlike Patterns::Double it refuses nan, inf, numbers that overflow or
   * underflow a double, and open bounds such as Re > 0 need no separate check. Its description reads
   * "[Finite number x with 0 < x ≤ 1]"; it is also the element pattern of lists of numbers.
   */
  class RealRange : public dealii::Patterns::PatternBase
  {
  public:
    enum class End
    {
      open,
      closed
    };

    RealRange(const double lower, const End lower_end, const double upper, const End upper_end);

    /// Any finite x.
    static RealRange
    any();
    /// x > @p lower (x > 0 by default).
    static RealRange
    above(const double lower = 0);
    /// x ≥ @p lower (x ≥ 0 by default).
    static RealRange
    at_least(const double lower = 0);
    /// @p lower ≤ x ≤ @p upper.
    static RealRange
    closed(const double lower, const double upper);
    /// @p lower < x < @p upper.
    static RealRange
    open(const double lower, const double upper);
    /// @p lower < x ≤ @p upper.
    static RealRange
    left_open(const double lower, const double upper);
    /// @p lower ≤ x < @p upper.
    static RealRange
    right_open(const double lower, const double upper);

    /// Whether @p x is finite and in the interval.
    bool
    contains(const double x) const;
    /// The interval as a condition on x: "0 < x ≤ 1", "x > 0", "any finite x".
    std::string
    condition() const;

    bool
    match(const std::string &test_string) const override;
    std::string
    description(const OutputStyle style = Machine) const override;
    std::unique_ptr<dealii::Patterns::PatternBase>
    clone() const override;

  private:
    double lower, upper;
    End    lower_end, upper_end;
  };

  /**
   * The value of the entry @p name of the current subsection as a vector of three numbers (its pattern is
   * a Patterns::List of length 3).
   */
  dealii::Tensor<1, 3>
  get_vector(const dealii::ParameterHandler &prm, const std::string &name);

  /**
   * An InputError about the value of an entry whose message does not yet name the parameter file
   * ("entry 'geometry/radius' = '2': expected 1 (…)"): the program, which knows the file, puts its name in
   * front ("FILE: entry …") when it reports the error (run_program(), run_simulation()).
   */
  class EntryError : public InputError
  {
  public:
    using InputError::InputError;
  };

  /**
   * A parameter file as parse_parameter_file() read it: its name, for messages, and the entries it sets,
   * for the scene rule (reject_entries_not_read()). An empty ParameterFile stands for parameters set in code
   * (ParameterHandler::set), which are not checked.
   */
  struct ParameterFile
  {
    /// An entry that the file sets: "subsection/entry" and the line of its `set`.
    struct Entry
    {
      std::string  path;
      unsigned int line = 0;
    };

    std::string        name;        ///< the file name; "" for parameters set in code
    std::vector<Entry> entries_set; ///< the `set` lines of the file (its included files not followed)

    /// The file as the start of a message: its name, or "parameters" for parameters set in code.
    std::string
    label() const;
  };

  /**
   * What a scene (or the command --equilibrium) reads of the parameter file: the subsections whose entries it
   * uses, and the entries of those subsections that it ignores. Every entry the file sets outside them is an
   * error (reject_entries_not_read()): an entry that changes nothing is a mistake of the user.
   */
  struct ParametersRead
  {
    std::string              reader;          ///< in messages: "scene stability", "--equilibrium"
    std::vector<std::string> subsections;     ///< the top-level subsections it reads
    std::vector<std::string> ignored_entries; ///< "subsection/entry" of those subsections that it does not use
  };

  /**
   * Reads @p filename into @p prm and returns its name and the entries it sets. Every failure of deal.II's parser
   * (missing file, unknown subsection or entry, a value that fails its pattern) becomes an InputError whose
   * message names the file, the line and what was expected; a value that fails its pattern as
   * "FILE, line N: entry 'subsection/entry' = 'value': expected PATTERN".
   */
  ParameterFile
  parse_parameter_file(dealii::ParameterHandler &prm, const std::string &filename);

  /**
   * Throws an EntryError "entry 'subsection/entry' = 'value': expected ..." for a value that passed its
   * pattern but is inconsistent with the others; the program names the file in front of it.
   */
  [[noreturn]] void
  throw_invalid_entry(const std::string &entry_path,
                      const std::string &value,
                      const std::string &expected);

  /**
   * Throws an InputError "FILE, line N: entry 'subsection/entry' is set, but scene S does not read subsection
   * 'subsection'; expected …" for the first entry that @p file sets outside what @p read reads (a subsection
   * it does not read, or one of its ignored entries), with the number of further such entries.
   */
  void
  reject_entries_not_read(const ParameterFile &file, const ParametersRead &read);

  /**
   * Prints every parameter as a valid parameter file: for each entry its help
   * text, its pattern and its default value (fluid_surface --print-parameters).
   */
  void
  print_documented_parameters(const dealii::ParameterHandler &prm, std::ostream &out);

  /**
   * The name of the last parameter file that parse_parameter_file() read ("" before). Deprecated: the last
   * global state of this file, kept only for reference/axisymmetric_equilibrium.cc, which names the file itself;
   * everything else gets the name from the ParameterFile or throws an EntryError.
   */
  const std::string &
  parameter_file_name();
} // namespace FluidSurface

#endif
