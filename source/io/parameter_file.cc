#include <fluid_surface/io/parameter_file.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>

namespace FluidSurface
{
  namespace
  {
    std::string current_parameter_file;

    /// An entry that a parameter file sets: "subsection/entry" and the line of its `set`.
    struct EntrySetInFile
    {
      std::string  path;
      unsigned int line;
    };
    /// The entries the last file read by parse_parameter_file() sets (its included files not followed).
    std::vector<EntrySetInFile> entries_set_in_file;

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
        entries_set_in_file = scan_entries_set(filename);
      }
    catch (const dealii::ExceptionBase &exc)
      {
        // deal.II's parser says "Line <N> of file <F>: ..."; we say "F, line N: ...".
        const std::string message = exception_message(exc);
        const std::regex  location("Line <([0-9]+)> of file <([^>:]*)>?:? ?");
        std::smatch       match;
        if (std::regex_search(message, match, location))
          throw InputError(filename + ", line " + match[1].str() + ": " + match.suffix().str());
        throw InputError(filename + ": " + message);
      }
    catch (const std::exception &exc)
      {
        throw InputError(filename + ": " + exc.what());
      }
  }

  void
  reject_entries_unused_by_scene(const std::vector<std::string> &unused, const std::string &scene)
  {
    for (const EntrySetInFile &entry : entries_set_in_file)
      for (const std::string &pattern : unused)
        {
          const bool whole_subsection = pattern.size() > 1 && pattern.compare(pattern.size() - 2, 2, "/*") == 0;
          const bool match            = whole_subsection ? entry.path.rfind(pattern.substr(0, pattern.size() - 1), 0) == 0 :
                                                           entry.path == pattern;
          if (match)
            throw InputError(current_parameter_file + ", line " + std::to_string(entry.line) + ": entry '" +
                             entry.path + "' is set, but scene " + scene +
                             " does not use it; expected no such entry (remove it, or choose the scene that uses it).");
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
