#include <fluid_surface/parameter_file.h>

#include <fstream>
#include <sstream>

namespace FluidSurface
{
  namespace
  {
    std::string current_parameter_file;

    /// The message of a deal.II exception without its source location block.
    std::string
    exception_message(const dealii::ExceptionBase &exc)
    {
      std::ostringstream out;
      exc.print_info(out);
      std::string message = out.str();
      // deal.II prefixes these messages with "    " and spreads them over lines.
      std::string compact;
      bool        in_space = true;
      for (const char c : message)
        {
          const bool space = (c == ' ' || c == '\n' || c == '\t');
          if (space && !in_space)
            compact += ' ';
          if (!space)
            compact += c;
          in_space = space;
        }
      while (!compact.empty() && compact.back() == ' ')
        compact.pop_back();
      return compact;
    }
  } // namespace

  const std::string &
  parameter_file_name()
  {
    return current_parameter_file;
  }

  void
  parse_parameter_file(dealii::ParameterHandler &prm, const std::string &filename)
  {
    current_parameter_file = filename;
    {
      std::ifstream probe(filename);
      if (!probe)
        throw InputError(filename + ": cannot open the parameter file (expected a readable .prm file).");
    }
    try
      {
        prm.parse_input(filename, "", /*skip_undefined=*/false, /*assert_mandatory_entries_are_found=*/false);
      }
    catch (const dealii::ExceptionBase &exc)
      {
        throw InputError(filename + ": " + exception_message(exc));
      }
    catch (const std::exception &exc)
      {
        throw InputError(filename + ": " + exc.what());
      }
  }

  void
  throw_invalid_entry(const std::string &entry_path,
                      const std::string &value,
                      const std::string &expected)
  {
    const std::string file = current_parameter_file.empty() ? std::string("parameters") : current_parameter_file;
    throw InputError(file + ": entry '" + entry_path + "' = '" + value + "': expected " + expected + ".");
  }
} // namespace FluidSurface
