#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>
#include <iostream>
#include <map>
#include <sstream>

namespace amfrac
{
  namespace
  {
    std::map<std::string, double>
    parse_constants(const std::string &text, const std::string &parameter)
    {
      std::map<std::string, double> constants{{"pi", M_PI}};
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const auto parts = Utilities::split_string_list(item, '=');
          double     value = 0;
          bool       ok    = parts.size() == 2 && !parts[0].empty();
          if (ok)
            {
              try
                {
                  value = Utilities::string_to_double(parts[1]);
                }
              catch (...)
                {
                  ok = false;
                }
            }
          require(ok,
                  parameter,
                  "a constant must read 'name=value', got '" + item + "'");
          constants[parts[0]] = value;
        }
      return constants;
    }

    std::string
    join(const std::vector<std::string> &parts)
    {
      std::string result;
      for (const auto &p : parts)
        result += (result.empty() ? "" : "; ") + p;
      return result;
    }
  } // namespace



  template <int dim>
  std::shared_ptr<Function<dim>>
  make_expression_function(const std::vector<std::string> &expressions,
                           const unsigned int              n_components,
                           const std::string              &constants,
                           const std::string              &parameter,
                           const std::string              &time_name)
  {
    std::vector<std::string> all = expressions;
    if (all.size() == 1)
      all.assign(n_components, expressions[0]);
    require(all.size() == n_components,
            parameter,
            "expects one expression or " + std::to_string(n_components)
              + " separated by ';', got " + std::to_string(expressions.size()));
    for (const auto &e : all)
      {
        require(!e.empty(), parameter, "an expression is empty");
        // muparser would read "a, b" as a list and keep one of them:
        // components are separated by ';', commas only separate function
        // arguments.
        int depth = 0;
        for (const char c : e)
          {
            depth += c == '(' ? 1 : c == ')' ? -1 : 0;
            require(c != ',' || depth > 0,
                    parameter,
                    "'" + e
                      + "' has a comma outside parentheses: separate the "
                        "components with ';'");
          }
      }

    auto function = std::make_shared<FunctionParser<dim>>(n_components);
    try
      {
        function->initialize(
          FunctionParser<dim>::default_variable_names() + "," + time_name,
          all,
          parse_constants(constants, "Boundary conditions/Function constants"),
          true);
        // muparser compiles lazily: evaluate once to reject bad input now,
        // with std::cerr muted because deal.II prints muparser's own report
        // there before throwing; ours names the parameter.
        dealii::Vector<double> probe(n_components);
        std::ostringstream     muted;
        std::streambuf        *saved = std::cerr.rdbuf(muted.rdbuf());
        try
          {
            function->vector_value(Point<dim>(), probe);
          }
        catch (...)
          {
            std::cerr.rdbuf(saved);
            throw;
          }
        std::cerr.rdbuf(saved);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream text;
        e.print_info(text);
        std::string message = text.str();
        for (auto &c : message)
          if (c == '\n')
            c = ' ';
        throw InputError(parameter,
                         "cannot parse '" + join(all)
                           + "': " + Utilities::trim(message));
      }
    catch (const std::exception &e)
      {
        throw InputError(parameter,
                         "cannot parse '" + join(all) + "': " + e.what());
      }
    return function;
  }

  template std::shared_ptr<Function<2>>
  make_expression_function<2>(const std::vector<std::string> &,
                              const unsigned int,
                              const std::string &,
                              const std::string &,
                              const std::string &);
  template std::shared_ptr<Function<3>>
  make_expression_function<3>(const std::vector<std::string> &,
                              const unsigned int,
                              const std::string &,
                              const std::string &,
                              const std::string &);
} // namespace amfrac
