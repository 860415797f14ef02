#ifndef fluid_surface_io_parameter_file_h
#define fluid_surface_io_parameter_file_h

#include <deal.II/base/parameter_handler.h>

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
   * Reads @p filename into @p prm. Every failure of deal.II's parser (missing
   * file, unknown subsection or entry, a value that fails its pattern) becomes
   * an InputError whose message names the file, the line and what was expected.
   */
  void
  parse_parameter_file(dealii::ParameterHandler &prm, const std::string &filename);

  /**
   * Throws an InputError "FILE: entry 'subsection/entry' = 'value': expected ..."
   * for a value that passed its pattern but is inconsistent with the others.
   */
  [[noreturn]] void
  throw_invalid_entry(const std::string &entry_path,
                      const std::string &value,
                      const std::string &expected);

  /// Throws an InputError "FILE, line N: entry 'subsection/entry' is set, but scene SCENE does not use it"
  /// for the first entry of @p unused that the last file read by parse_parameter_file() sets. An element of
  /// @p unused is "subsection/entry", or "subsection/*" for every entry of a subsection. Entries set by
  /// other means (ParameterHandler::set) are not checked.
  void
  reject_entries_unused_by_scene(const std::vector<std::string> &unused, const std::string &scene);

  /**
   * Prints every parameter as a valid parameter file: for each entry its help
   * text, its pattern and its default value (fluid_surface --print-parameters).
   */
  void
  print_documented_parameters(const dealii::ParameterHandler &prm, std::ostream &out);

  /**
   * The name of the parameter file that was read, for messages ("" before).
   */
  const std::string &
  parameter_file_name();
} // namespace FluidSurface

#endif
