#include "cli/commands.hpp"

namespace sl {

void addCommands(CLI::App& app) {
  addRenderCommand(app);
  addStillCommand(app);
  addContactSheetCommand(app);
  addSimulateCommand(app);
  addValidateCommand(app);
  addDiffCommand(app);
  addListMethodsCommand(app);
  addBenchCommand(app);
  addStabilityCommand(app);
  addGeometryCommand(app);
  addNumbersCommand(app);
  addConnectCommand(app);
  addPeriodicCommand(app);
  addSchemaCommand(app);
}

}  // namespace sl
