#include <amfrac/app/command_line.h>
#include <amfrac/checkpoint/checkpoint_store.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <cctype>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace
{
  const char *usage
    = "usage: amfrac [options] FILE.prm\n"
      "       mpirun -np N amfrac FILE.prm\n"
      "\n"
      "Adaptive Multi-FRActure analysis of Composites: runs the scene that\n"
      "FILE.prm describes and writes its output to Output/Directory.\n"
      "\n"
      "options:\n"
      "  -h, --help              this text\n"
      "  -p, --print-parameters  every parameter with its default, pattern\n"
      "                          and documentation (units in brackets)\n"
      "  --resume DIR            continue from the newest complete checkpoint\n"
      "                          in DIR (Checkpoint/Directory, by default\n"
      "                          <Output/Directory>/checkpoints) with the\n"
      "                          parameters stored in it, or with FILE.prm\n"
      "                          if given\n"
      "\n"
      "exit status: 0 done; 1 bad input or a failed run (the message names\n"
      "the parameter or the cause); 2 usage; 75 stopped with a checkpoint\n"
      "(SIGTERM, SIGINT or Checkpoint/Stop after step): resume it\n";

  void
  print_parameters()
  {
    dealii::ParameterHandler prm;
    amfrac::parameters::Parameters::declare_parameters(prm);
    prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
  }

  /** One line on rank 0 (white space folded), non-zero exit status. */
  int
  fail(const std::string &message, const bool is_root)
  {
    std::string line;
    for (const char c : message)
      if (!std::isspace(static_cast<unsigned char>(c)))
        line += c;
      else if (!line.empty() && line.back() != ' ')
        line += ' ';
    if (is_root)
      std::cerr << "amfrac: error: " << line << std::endl;
    return 1;
  }

  /** An error that may have happened on this rank only: say it, then end
   * every rank (the others may wait in a collective call). */
  int
  fail_locally(const std::string &message, const MPI_Comm comm)
  {
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    fail(n_ranks > 1 ? "(rank " + std::to_string(rank) + ") " + message :
                       message,
         true);
    if (n_ranks > 1)
      MPI_Abort(comm, 1);
    return 1;
  }

  amfrac::CheckpointStore::Contents
  read_checkpoint(const std::string &directory, const MPI_Comm comm)
  {
    const std::string folder = amfrac::CheckpointStore::newest(directory, comm);
    if (folder.empty())
      throw amfrac::InputError("--resume: no complete checkpoint in '"
                               + directory
                               + "' (a folder checkpoint-<n> with run.h5)");
    return amfrac::CheckpointStore::read(folder, comm);
  }

  template <int dim>
  void
  run(const amfrac::parameters::Parameters    &parameters,
      const amfrac::CheckpointStore::Contents *checkpoint,
      const MPI_Comm                           comm)
  {
    amfrac::Simulator<dim> simulator(parameters, comm);
    if (checkpoint)
      simulator.resume(*checkpoint);
    simulator.run();
  }
} // namespace



int
amfrac::command_line(const std::vector<std::string> &arguments,
                     const MPI_Comm                  comm)
{
  const bool is_root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  dealii::deal_II_exceptions::disable_abort_on_exception();

  std::string file, resume_directory;
  for (std::size_t i = 0; i < arguments.size(); ++i)
    {
      const std::string &arg = arguments[i];
      if (arg == "--resume")
        {
          if (i + 1 == arguments.size())
            return fail("--resume needs the checkpoint folder", is_root);
          resume_directory = arguments[++i];
          continue;
        }
      if (arg == "-h" || arg == "--help")
        {
          if (is_root)
            std::cout << usage;
          return 0;
        }
      if (arg == "-p" || arg == "--print-parameters")
        {
          if (is_root)
            print_parameters();
          return 0;
        }
      if (!arg.empty() && arg[0] == '-')
        return fail("unknown option '" + arg + "' (see amfrac --help)",
                    is_root);
      if (!file.empty())
        return fail("more than one parameter file given", is_root);
      file = arg;
    }
  if (file.empty() && resume_directory.empty())
    {
      if (is_root)
        std::cerr << usage;
      return 2;
    }

  try
    {
      std::unique_ptr<amfrac::CheckpointStore::Contents> checkpoint;
      if (!resume_directory.empty())
        checkpoint = std::make_unique<amfrac::CheckpointStore::Contents>(
          read_checkpoint(resume_directory, comm));
      const auto parameters = file.empty() ?
                                amfrac::parameters::Parameters::from_string(
                                  checkpoint->run.get_text("parameters")) :
                                amfrac::parameters::Parameters::from_file(file);
      if (parameters.dimension == 2)
        run<2>(parameters, checkpoint.get(), comm);
      else
        run<3>(parameters, checkpoint.get(), comm);
    }
  catch (const amfrac::RunInterrupted &e)
    {
      if (is_root)
        std::cout << "amfrac: " << e.what() << std::endl;
      return 75;
    }
  catch (const amfrac::InputError &e)
    {
      const std::string message = e.what();
      return fail(message.find(file) == std::string::npos && !file.empty() ?
                    message + " [in " + file + "]" :
                    message,
                  is_root);
    }
  catch (const amfrac::CollectiveError &e)
    {
      return fail(e.what(), is_root);
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::ostringstream text;
      e.print_info(text);
      return fail_locally(text.str(), comm);
    }
  catch (const std::exception &e)
    {
      return fail_locally(e.what(), comm);
    }
  return 0;
}
