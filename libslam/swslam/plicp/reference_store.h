#pragma once
// The graph nodes' reference scans for as long as a mission lasts. Each node's scan is kept
// compact (sensor/compact_scan.h: 8 bytes a valid ray); the reference form PLICP matches
// against (ReferenceScan: the Scan's doubles and points, the search tables, some 45 KB for a
// 1081-ray scan) is kept only for the nodes used last and rebuilt when an older one is
// matched again. A rebuilt scan is the same bit for bit, so which ones are kept never changes
// a result. Thread-safe: the tracking and graph threads share one store.

#include <swslam/plicp/plicp.h>
#include <swslam/sensor/compact_scan.h>

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace swslam::plicp
{
class ReferenceStore
{
 public:
  /** Reference forms kept by default: more than tracking's dense neighbours and loop
   * candidates of one place (about 11 MB for 1081-ray scans). */
  static constexpr size_t kBuiltKept = 256;

  /** `params.min_segment_length` shapes the search tables the store builds. */
  explicit ReferenceStore(const PlicpParams& params, size_t built_kept = kBuiltKept);

  /** Adds node `id`'s scan, `built` (its reference form, built with this store's parameters),
   * as the one used last. Ids come in order: 0, 1, 2, ...; throws std::invalid_argument for
   * another id, a null scan, or one whose tables were built for another segment length. */
  void add(size_t id, std::shared_ptr<const ReferenceScan> built);

  /** Node `id`'s reference scan, rebuilt if it is no longer kept. Throws std::out_of_range for
   * an id not added or released. */
  std::shared_ptr<const ReferenceScan> get(size_t id) const;

  /** Forgets node `id`'s scan (a node merged into another is not matched again); its id
   * stays taken. Throws std::out_of_range for an id not added. */
  void release(size_t id);
  /** Takes the next id with no scan, as if added and released (a restored node merged into
   * another). Throws std::invalid_argument for another id than the next. */
  void addReleased(size_t id);

  size_t size() const;
  /** Reference forms held now. */
  size_t builtCount() const;
  /** Memory of the compact scans and of the reference forms held [bytes, approximately]. */
  size_t bytes() const;

 private:
  /** Makes `id` the one used last, holding `built`; drops the least recently used past the
   * bound. Called with mutex_ held. */
  void keep(size_t id, std::shared_ptr<const ReferenceScan> built) const;

  const PlicpParams params_;
  const size_t built_kept_;
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<const sensor::CompactScan>> compact_;  ///< by node id
  struct Built
  {
    std::shared_ptr<const ReferenceScan> scan;
    std::list<size_t>::iterator use;  ///< its place in uses_
  };
  mutable std::unordered_map<size_t, Built> built_;
  mutable std::list<size_t> uses_;  ///< node ids, used last first
};

/** Approximate memory of a reference scan (its Scan and search tables) [bytes]. */
size_t referenceScanBytes(const ReferenceScan& r);

}  // namespace swslam::plicp
