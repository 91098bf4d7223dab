// Harness: graph::readGraph over any bytes as a .graph / g2o / TORO file, then the graph it
// read written (writeGraph) and read again. Documented error path: std::runtime_error naming
// the source (and line). Promises checked: what was read writes back into a file that reads
// without error or skipped line, with the same vertices, edges and root.

#include "fuzz_input.h"

#include <swslam/graph/io.h>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  graph::GraphLoadReport report;
  graph::PoseGraph g;
  try
  {
    g = graph::readGraph(in, "input", &report);
  }
  catch (const std::runtime_error& e)
  {
    SWSLAM_FUZZ_CHECK(fuzz::startsWith(e.what(), "input:"), e.what());
    return 0;
  }
  SWSLAM_FUZZ_CHECK(report.vertices == g.nodeCount() && report.edges == g.edgeCount(), "report");
  SWSLAM_FUZZ_CHECK(report.skipped_line_numbers.size() == report.skipped_lines &&
                        report.skip_reasons.size() == report.skipped_lines,
                    "report");

  std::stringstream text;
  graph::writeGraph(g, text);
  graph::GraphLoadReport again;
  const graph::PoseGraph back = graph::readGraph(text, "written", &again);
  SWSLAM_FUZZ_CHECK(back.nodeCount() == g.nodeCount() && back.edgeCount() == g.edgeCount() &&
                        back.root() == g.root() && again.skipped_lines == 0,
                    text.str());
  return 0;
}
