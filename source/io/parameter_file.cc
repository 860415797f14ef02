// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <locale>
#include <regex>
#include <sstream>

namespace FluidSurface
{
  namespace
  {
    /// For parameter_file_name() only (deprecated).
    std::string last_parameter_file;

    using EntrySetInFile = ParameterFile::Entry;

    std::string
    trim(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\r");
      if (first == std::string::npos)
        return "";
      return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
    }

    /// The `set` lines of @p filename with their subsection paths, as ParameterHandler reads them
    /// (comments after #, lines continued by a trailing backslash).
    std::vector<EntrySetInFile>
    scan_entries_set(const std::string &filename)
    {
      std::vector<EntrySetInFile> entries;
      std::vector<std::string>    subsections;
      std::ifstream               in(filename);
      std::string                 line, logical;
      unsigned int                number = 0, first_line = 0;
      while (std::getline(in, line))
        {
          ++number;
          if (logical.empty())
            first_line = number;
          line = trim(line.substr(0, line.find('#')));
          if (!line.empty() && line.back() == '\\')
            {
              logical += line.substr(0, line.size() - 1) + ' ';
              continue;
            }
          logical += line;
          std::istringstream words(logical);
          std::string        keyword;
          words >> keyword;
          if (keyword == "subsection")
            subsections.push_back(trim(logical.substr(keyword.size())));
          else if (keyword == "end" && !subsections.empty())
            subsections.pop_back();
          else if (keyword == "set")
            {
              std::string path;
              for (const std::string &subsection : subsections)
                path += subsection + '/';
              const std::string assignment = logical.substr(keyword.size());
              entries.push_back({path + trim(assignment.substr(0, assignment.find('='))), first_line});
            }
          logical.clear();
        }
      return entries;
    }

    /// Undoes ParameterHandler's mangling of names ("_20" for a space).
    std::string
    demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() && std::isxdigit(name[i + 1]) && std::isxdigit(name[i + 2]))
          {
            out += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    /// Wraps @p text into comment lines of at most 100 characters.
    void
    print_comment(std::ostream &out, const std::string &indent, const std::string &text)
    {
      std::istringstream words(text);
      std::string        word, line;
      while (words >> word)
        {
          if (!line.empty() && line.size() + word.size() + 1 > 96 - indent.size())
            {
              out << indent << "# " << line << '\n';
              line.clear();
            }
          line += (line.empty() ? "" : " ") + word;
        }
      if (!line.empty())
        out << indent << "# " << line << '\n';
    }

    void
    print_tree(const boost::property_tree::ptree &tree, std::ostream &out, const std::string &indent)
    {
      for (const auto &child : tree)
        if (child.second.count("value") > 0 && child.second.count("pattern_description") > 0)
          {
            print_comment(out, indent, child.second.get<std::string>("documentation"));
            print_comment(out, indent, "Pattern: " + child.second.get<std::string>("pattern_description"));
            out << indent << "set " << demangle(child.first) << " = "
                << child.second.get<std::string>("default_value") << "\n\n";
          }
      for (const auto &child : tree)
        if (child.second.count("value") == 0 && !child.second.empty())
          {
            out << indent << "subsection " << demangle(child.first) << '\n';
            print_tree(child.second, out, indent + "  ");
            out << indent << "end\n\n";
          }
    }
  } // namespace

  void
  print_documented_parameters(const dealii::ParameterHandler &prm, std::ostream &out)
  {
    std::stringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    out << "# fluid_surface: every parameter with its help text, pattern and default value.\n\n";
    print_tree(tree, out, "");
  }

  // ------------------------------------------------------------------ RealRange

  namespace
  {
    /// @p x as one writes it in a parameter file: 0.5, 1000, 1e-6, 1e6.
    std::string
    number_text(const double x)
    {
      std::ostringstream out;
      if (x != 0 && (std::abs(x) >= 1e5 || std::abs(x) < 1e-3))
        out << std::scientific;
      out << std::setprecision(std::abs(x) >= 1e5 || (x != 0 && std::abs(x) < 1e-3) ? 14 : 15) << x;
      std::string text = out.str();
      // Without trailing zeros of the mantissa and with a short exponent: 1.000e+06 → 1e6.
      text = std::regex_replace(text, std::regex("\\.?0+e"), "e");
      return std::regex_replace(text, std::regex("e\\+?(-?)0*([0-9])"), "e$1$2");
    }
  } // namespace

  RealRange::RealRange(const double lower, const End lower_end, const double upper, const End upper_end)
    : lower(lower)
    , upper(upper)
    , lower_end(std::isfinite(lower) ? lower_end : End::open)
    , upper_end(std::isfinite(upper) ? upper_end : End::open)
  {}

  RealRange
  RealRange::any()
  {
    const double inf = std::numeric_limits<double>::infinity();
    return RealRange(-inf, End::open, inf, End::open);
  }

  RealRange
  RealRange::above(const double lower)
  {
    return RealRange(lower, End::open, std::numeric_limits<double>::infinity(), End::open);
  }

  RealRange
  RealRange::at_least(const double lower)
  {
    return RealRange(lower, End::closed, std::numeric_limits<double>::infinity(), End::open);
  }

  RealRange
  RealRange::closed(const double lower, const double upper)
  {
    return RealRange(lower, End::closed, upper, End::closed);
  }

  RealRange
  RealRange::open(const double lower, const double upper)
  {
    return RealRange(lower, End::open, upper, End::open);
  }

  RealRange
  RealRange::left_open(const double lower, const double upper)
  {
    return RealRange(lower, End::open, upper, End::closed);
  }

  RealRange
  RealRange::right_open(const double lower, const double upper)
  {
    return RealRange(lower, End::closed, upper, End::open);
  }

  bool
  RealRange::contains(const double x) const
  {
    return std::isfinite(x) && (lower_end == End::open ? x > lower : x >= lower) &&
           (upper_end == End::open ? x < upper : x <= upper);
  }

  std::string
  RealRange::condition() const
  {
    const bool        has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
    const std::string lower_relation = (lower_end == End::open ? " < " : " ≤ ");
    const std::string upper_relation = (upper_end == End::open ? " < " : " ≤ ");
    if (!has_lower && !has_upper)
      return "any finite number";
    if (!has_upper)
      return std::string("x") + (lower_end == End::open ? " > " : " ≥ ") + number_text(lower);
    if (!has_lower)
      return "x" + upper_relation + number_text(upper);
    return number_text(lower) + lower_relation + "x" + upper_relation + number_text(upper);
  }

  bool
  RealRange::match(const std::string &test_string) const
  {
    // The whole text must be one number, read as ParameterHandler::get_double() reads it.
    std::istringstream in(test_string);
    in.imbue(std::locale::classic());
    double x = 0;
    if (!(in >> x) || !(in >> std::ws).eof())
      return false;
    try
      {
        if (dealii::Utilities::string_to_double(test_string) != x)
          return false;
      }
    catch (...)
      {
        return false;
      }
    return contains(x);
  }

  std::string
  RealRange::description(const OutputStyle) const
  {
    if (!std::isfinite(lower) && !std::isfinite(upper))
      return "[Finite number]";
    return "[Finite number x with " + condition() + "]";
  }

  std::unique_ptr<dealii::Patterns::PatternBase>
  RealRange::clone() const
  {
    return std::make_unique<RealRange>(*this);
  }

  // ------------------------------------------------------------------ reading entries

  dealii::Tensor<1, 3>
  get_vector(const dealii::ParameterHandler &prm, const std::string &name)
  {
    const std::vector<std::string> items = dealii::Utilities::split_string_list(prm.get(name));
    AssertThrow(items.size() == 3, dealii::ExcMessage("entry '" + name + "' is not a list of three numbers"));
    dealii::Tensor<1, 3> v;
    for (unsigned int d = 0; d < 3; ++d)
      v[d] = dealii::Utilities::string_to_double(items[d]);
    return v;
  }

  const std::string &
  parameter_file_name()
  {
    return last_parameter_file;
  }

  std::string
  ParameterFile::label() const
  {
    return name.empty() ? std::string("parameters") : name;
  }

  ParameterFile
  parse_parameter_file(dealii::ParameterHandler &prm, const std::string &filename)
  {
    last_parameter_file = filename;
    {
      std::ifstream probe(filename);
      if (!probe)
        throw InputError(filename + ": cannot open the parameter file (expected a readable .prm file).");
    }
    try
      {
        prm.parse_input(filename, "", /*skip_undefined=*/false, /*assert_mandatory_entries_are_found=*/false);
        return ParameterFile{filename, scan_entries_set(filename)};
      }
    catch (const dealii::ExceptionBase &exc)
      {
        // deal.II's parser says "Line <N> of file <F>: ..."; we say "F, line N: ...".
        // deal.II spreads these messages over indented lines.
        const std::string message = one_line_message(exc, std::string::npos);
        const std::regex  location("Line <([0-9]+)> of file <([^>:]*)>?:? ?");
        std::smatch       match;
        if (std::regex_search(message, match, location))
          {
            const std::string line = match[1].str(), text = match.suffix().str();
            // A value that fails its pattern: name the entry with its subsections, like throw_invalid_entry().
            const std::regex bad_value("The entry value ?(.*) for the entry named (.*) does not match the given "
                                       "pattern: (.*)");
            std::smatch      value_match;
            if (std::regex_match(text, value_match, bad_value))
              {
                std::string path = value_match[2].str();
                for (const EntrySetInFile &entry : scan_entries_set(filename))
                  if (std::to_string(entry.line) == line && entry.path.size() >= path.size() &&
                      entry.path.compare(entry.path.size() - path.size(), path.size(), path) == 0)
                    path = entry.path;
                throw InputError(filename + ", line " + line + ": entry '" + path + "' = '" + value_match[1].str() +
                                 "': expected " + value_match[3].str() + ".");
              }
            throw InputError(filename + ", line " + line + ": " + text);
          }
        throw InputError(filename + ": " + message);
      }
    catch (const std::exception &exc)
      {
        throw InputError(filename + ": " + exc.what());
      }
  }

  void
  reject_entries_not_read(const ParameterFile &file, const ParametersRead &read)
  {
    const ParameterFile::Entry *first     = nullptr;
    unsigned int                n_outside = 0;
    std::string                 reason;
    for (const ParameterFile::Entry &entry : file.entries_set)
      {
        const std::string subsection = entry.path.substr(0, entry.path.find('/'));
        std::string       why;
        if (std::find(read.subsections.begin(), read.subsections.end(), subsection) == read.subsections.end())
          why = "does not read subsection '" + subsection + "'";
        else if (std::find(read.ignored_entries.begin(), read.ignored_entries.end(), entry.path) !=
                 read.ignored_entries.end())
          why = "ignores it";
        if (why.empty())
          continue;
        if (first == nullptr)
          first = &entry, reason = why;
        ++n_outside;
      }
    if (first == nullptr)
      return;
    const std::string more = n_outside == 1 ? std::string() :
                                              " (and " + std::to_string(n_outside - 1) + " more such " +
                                                (n_outside == 2 ? "entry" : "entries") + ")";
    throw InputError(file.label() + ", line " + std::to_string(first->line) + ": entry '" + first->path +
                     "' is set, but " + read.reader + " " + reason + more +
                     "; expected no such entry (remove it, or choose a scene that reads it).");
  }

  void
  throw_invalid_entry(const std::string &entry_path,
                      const std::string &value,
                      const std::string &expected)
  {
    throw EntryError("entry '" + entry_path + "' = '" + value + "': expected " + expected + ".");
  }
} // namespace FluidSurface
