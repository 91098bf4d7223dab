#include <swslam/graph/io.h>

#include <swslam/common/atomic_file.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace swslam::graph
{
namespace
{
struct EdgeRecord
{
  size_t line;
  PoseGraph::TNodeID from, to;
  mrpt::poses::CPosePDFGaussianInf z;
  EdgeKind kind;
  bool switched_off;
  bool merged;  ///< "kind=merged": `to` is merged into `from` (PoseGraph::merge)
};

/** Reads exactly `n` numbers and nothing else; false on any parse error. strtod reads
 * "nan" and "inf" too, so such values reach validation and become errors, not skips. */
bool readNumbers(std::istringstream& s, double* v, int n)
{
  std::string token;
  for (int k = 0; k < n; ++k)
  {
    if (!(s >> token)) return false;
    char* end = nullptr;
    v[k] = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') return false;
  }
  return !(s >> token);
}

/** Places the vertices that only the edges name (an edge-only g2o file, as SE-Sync's CSAIL,
 * M3500 or KITTI): each reached from a placed vertex by an edge, its measurement composed
 * (inverted when walked backwards), odometry edges (to == from + 1) before any other; a vertex
 * no edge reaches from a placed one starts a piece of its own at the origin. Returns the
 * number placed and, in `pieces`, the pieces started so. */
size_t placeMissingVertices(PoseGraph& graph, const std::vector<EdgeRecord>& edges, size_t& pieces)
{
  std::map<PoseGraph::TNodeID, std::vector<size_t>> at;
  for (size_t k = 0; k < edges.size(); ++k)
  {
    at[edges[k].from].push_back(k);
    at[edges[k].to].push_back(k);
  }
  // 0-1 breadth first: an odometry edge costs nothing, any other one step, so that a vertex
  // is placed along the chain wherever the chain reaches it. A vertex is placed when it leaves
  // the queue, from the edge that reached it at the least cost.
  struct Reach
  {
    size_t cost;
    size_t edge;
    PoseGraph::TNodeID from;
  };
  std::map<PoseGraph::TNodeID, Reach> best;
  std::deque<PoseGraph::TNodeID> queue;
  for (const auto& [id, incident] : at)
    if (graph.hasNode(id)) queue.push_back(id), best[id] = {0, 0, id};
  size_t placed = 0;
  pieces = 0;
  auto grow = [&]() {
    std::set<PoseGraph::TNodeID> done;
    while (!queue.empty())
    {
      const PoseGraph::TNodeID p = queue.front();
      queue.pop_front();
      if (!done.insert(p).second) continue;
      if (!graph.hasNode(p))
      {
        const Reach& r = best.at(p);
        const EdgeRecord& e = edges[r.edge];
        const mrpt::poses::CPose2D& z = e.z.mean;
        graph.addNode(p, e.from == r.from ? graph.pose(r.from) + z : graph.pose(r.from) + (-z));
        ++placed;
      }
      const size_t cost = best.at(p).cost;
      for (const size_t k : at[p])
      {
        const EdgeRecord& e = edges[k];
        const PoseGraph::TNodeID q = e.from == p ? e.to : e.from;
        if (done.count(q) || graph.hasNode(q)) continue;
        const bool odometry = e.to == e.from + 1;
        const size_t c = cost + (odometry ? 0 : 1);
        const auto it = best.find(q);
        if (it != best.end() && it->second.cost <= c) continue;
        best[q] = {c, k, p};
        if (odometry)
          queue.push_front(q);
        else
          queue.push_back(q);
      }
    }
  };
  grow();
  for (const auto& [id, incident] : at)
    if (!graph.hasNode(id))
    {
      graph.addNode(id, mrpt::poses::CPose2D());
      ++placed, ++pieces;
      best[id] = {0, 0, id};
      queue.push_back(id);
      grow();
    }
  return placed;
}

std::string lineTag(const std::string& source, size_t line)
{
  return source + ":" + std::to_string(line) + ": ";
}

EdgeKind edgeKindOf(const std::string& comment, PoseGraph::TNodeID from, PoseGraph::TNodeID to)
{
  const auto at = comment.find("kind=");
  if (at != std::string::npos)
  {
    std::istringstream s(comment.substr(at + 5));
    std::string name;
    s >> name;
    if (const auto kind = edgeKindFromName(name)) return *kind;
  }
  return to == from + 1 ? EdgeKind::Consecutive : EdgeKind::Loop;
}

/** An EDGE_SE2 (g2o) or EDGE2 / EDGE (TORO) line's record, read after its keyword; none if
 * it is malformed. */
std::optional<EdgeRecord> edgeRecord(std::istringstream& s, bool g2o, size_t line, const std::string& comment)
{
  long long id1 = -1, id2 = -1;
  double v[9];
  if (!(s >> id1 >> id2) || id1 < 0 || id2 < 0 || !readNumbers(s, v, 9)) return std::nullopt;
  mrpt::math::CMatrixDouble33 I;
  if (g2o)  // I11 I12 I13 I22 I23 I33
    I.asEigen() << v[3], v[4], v[5], v[4], v[6], v[7], v[5], v[7], v[8];
  else  // TORO: I11 I12 I22 I33 I13 I23
    I.asEigen() << v[3], v[4], v[7], v[4], v[5], v[8], v[7], v[8], v[6];
  return EdgeRecord{line,
                    PoseGraph::TNodeID(id1),
                    PoseGraph::TNodeID(id2),
                    mrpt::poses::CPosePDFGaussianInf(mrpt::poses::CPose2D(v[0], v[1], v[2]), I),
                    edgeKindOf(comment, id1, id2),
                    comment.find("switched_off") != std::string::npos,
                    comment.find("kind=merged") != std::string::npos};
}

/** The file's edges into `graph` but the "kind=merged" records: the vertices only edges name
 * placed first. */
void addEdges(PoseGraph& graph, const std::vector<EdgeRecord>& edges, const std::string& source, GraphLoadReport& rep)
{
  for (const auto& e : edges)
    if (!std::isfinite(e.z.mean.x()) || !std::isfinite(e.z.mean.y()) || !std::isfinite(e.z.mean.phi()))
      throw std::runtime_error(lineTag(source, e.line) + "edge " + std::to_string(e.from) + " -> " +
                               std::to_string(e.to) + ": measurement is not finite");
  rep.placed_vertices = placeMissingVertices(graph, edges, rep.placed_pieces);
  for (const auto& e : edges)
  {
    if (e.merged) continue;
    try
    {
      const auto added = graph.addEdge(e.from, e.to, e.z, e.kind);
      if (e.switched_off && added) rep.switched_off.push_back(*added);
    }
    catch (const std::invalid_argument& ex)
    {
      throw std::runtime_error(lineTag(source, e.line) + ex.what());
    }
  }
}

/** The "kind=merged" records, in id order (an anchor is older than the nodes merged into it),
 * once the root is known (it stays a node). */
void applyMerges(PoseGraph& graph, const std::vector<EdgeRecord>& edges, const std::string& source)
{
  std::vector<const EdgeRecord*> merges;
  for (const auto& e : edges)
    if (e.merged) merges.push_back(&e);
  std::stable_sort(merges.begin(), merges.end(), [](auto* a, auto* b) { return a->to < b->to; });
  for (const EdgeRecord* e : merges)
  {
    try
    {
      graph.merge(e->to, e->from, e->z);
    }
    catch (const std::invalid_argument& ex)
    {
      throw std::runtime_error(lineTag(source, e->line) + ex.what());
    }
  }
}
}  // namespace

PoseGraph readGraph(std::istream& in, const std::string& source, GraphLoadReport* report)
{
  GraphLoadReport rep;
  PoseGraph graph;
  std::vector<EdgeRecord> edges;
  bool have_fix = false;
  PoseGraph::TNodeID fix_id = 0;
  size_t fix_line = 0;
  auto skip = [&](size_t line, const std::string& why) {
    ++rep.skipped_lines;
    rep.skipped_line_numbers.push_back(line);
    rep.skip_reasons.push_back(why);
  };
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line)
  {
    const size_t cut = text.find_first_of("#|");
    const std::string comment = cut == std::string::npos ? "" : text.substr(cut);
    std::istringstream s(text.substr(0, cut));
    std::string key;
    if (!(s >> key)) continue;  // blank or comment-only
    const bool g2o_vertex = key == "VERTEX_SE2";
    const bool toro_vertex = key == "VERTEX2" || key == "VERTEX";
    const bool g2o_edge = key == "EDGE_SE2";
    const bool toro_edge = key == "EDGE2" || key == "EDGE";
    long long id1 = -1;
    double v[3];
    if (g2o_vertex || toro_vertex)
    {
      if (!(s >> id1) || id1 < 0 || !readNumbers(s, v, 3))
      {
        skip(line, "malformed " + key + " line");
        continue;
      }
      try
      {
        graph.addNode(id1, mrpt::poses::CPose2D(v[0], v[1], v[2]));
      }
      catch (const std::invalid_argument& e)
      {
        throw std::runtime_error(lineTag(source, line) + e.what());
      }
    }
    else if (g2o_edge || toro_edge)
    {
      if (auto e = edgeRecord(s, g2o_edge, line, comment)) edges.push_back(*e);
      else skip(line, "malformed " + key + " line");
    }
    else if (key == "FIX")
    {
      if (!(s >> id1) || id1 < 0) skip(line, "malformed FIX line");
      else if (have_fix) skip(line, "extra FIX (only the first is the gauge)");
      else have_fix = true, fix_id = id1, fix_line = line;
    }
    else if (key == "EQUIV")
      skip(line, "EQUIV (node merging) is not supported");
    else
      skip(line, "unknown keyword '" + key + "'");
  }
  if (graph.nodeCount() == 0 && edges.empty()) throw std::runtime_error(source + ": no vertex and no edge in the file");
  addEdges(graph, edges, source, rep);
  if (have_fix)
  {
    if (!graph.hasNode(fix_id))
      throw std::runtime_error(lineTag(source, fix_line) + "FIX names missing node " +
                               std::to_string(fix_id));
    graph.setRoot(fix_id);
  }
  applyMerges(graph, edges, source);
  rep.vertices = graph.nodeCount();
  rep.edges = graph.edgeCount();
  if (report) *report = rep;
  return graph;
}

PoseGraph loadGraph(const std::string& path, GraphLoadReport* report)
{
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open graph file '" + path + "'");
  return readGraph(in, path, report);
}

namespace
{
/** An EDGE_SE2 line: ids, mean, the information's upper triangle (g2o order), the comment. */
void writeEdge(std::ostream& out, PoseGraph::TNodeID from, PoseGraph::TNodeID to,
               const mrpt::poses::CPosePDFGaussianInf& z, const std::string& comment)
{
  const auto& m = z.mean;
  const auto& I = z.cov_inv;
  out << "EDGE_SE2 " << from << ' ' << to << ' ' << m.x() << ' ' << m.y() << ' ' << m.phi() << ' ' << I(0, 0) << ' '
      << I(0, 1) << ' ' << I(0, 2) << ' ' << I(1, 1) << ' ' << I(1, 2) << ' ' << I(2, 2) << " # " << comment << '\n';
}
}  // namespace

void writeGraph(const PoseGraph& graph, std::ostream& out, const std::vector<size_t>& switched_off)
{
  std::vector<char> off(graph.edgeCount(), 0);
  for (const size_t k : switched_off)
    if (k < off.size()) off[k] = 1;
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (const auto id : graph.nodeIds())
  {
    const auto& p = graph.pose(id);
    out << "VERTEX_SE2 " << id << ' ' << p.x() << ' ' << p.y() << ' ' << p.phi() << '\n';
  }
  if (graph.nodeCount() > 0) out << "FIX " << graph.root() << '\n';
  for (size_t k = 0; k < graph.edgeCount(); ++k)
  {
    const auto& e = graph.edge(k);
    writeEdge(out, e.from, e.to, *e.measurement, std::string("kind=") + edgeKindName(e.kind) + (off[k] ? " switched_off" : ""));
  }
  for (const auto& [id, a] : graph.merged()) writeEdge(out, a.anchor, id, a.z, "kind=merged");
}

void saveGraph(const PoseGraph& graph, const std::string& path, const std::vector<size_t>& switched_off)
{
  common::writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error("cannot write graph file '" + tmp + "'");
    writeGraph(graph, out, switched_off);
    if (!out) throw std::runtime_error("error writing graph file '" + tmp + "'");
  });
}

}  // namespace swslam::graph
