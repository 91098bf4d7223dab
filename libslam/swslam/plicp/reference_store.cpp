#include <swslam/plicp/reference_store.h>

#include <stdexcept>
#include <string>

namespace swslam::plicp
{
namespace
{
template <class T>
size_t vectorBytes(const std::vector<T>& v)
{
  return v.capacity() * sizeof(T);
}
}  // namespace

size_t referenceScanBytes(const ReferenceScan& r)
{
  const sensor::Scan& s = r.scan;
  const ReferenceIndex& i = r.index;
  return sizeof(r) + vectorBytes(s.angles) + vectorBytes(s.ranges) + vectorBytes(s.points) +
         vectorBytes(s.beam_index) + vectorBytes(i.up_bigger) + vectorBytes(i.up_smaller) +
         vectorBytes(i.down_bigger) + vectorBytes(i.down_smaller) + vectorBytes(i.dirs) +
         vectorBytes(i.pseudo) + vectorBytes(i.segment_lo) + vectorBytes(i.segment_hi) +
         vectorBytes(i.normal_lo) + vectorBytes(i.normal_hi);
}

ReferenceStore::ReferenceStore(const PlicpParams& params, size_t built_kept)
    : params_(params), built_kept_(built_kept)
{
  if (built_kept_ == 0) throw std::invalid_argument("ReferenceStore: keep at least one reference scan");
}

void ReferenceStore::add(size_t id, std::shared_ptr<const ReferenceScan> built)
{
  if (!built) throw std::invalid_argument("ReferenceStore: node " + std::to_string(id) + " has no scan");
  if (built->index.min_segment != params_.min_segment_length)
    throw std::invalid_argument("ReferenceStore: node " + std::to_string(id) +
                                "'s search tables were built for another min_segment_length");
  auto compact = std::make_shared<const sensor::CompactScan>(sensor::compactScan(built->scan));
  std::lock_guard<std::mutex> lock(mutex_);
  if (id != compact_.size())
    throw std::invalid_argument("ReferenceStore: node " + std::to_string(id) + " added after " +
                                std::to_string(compact_.size()) + " nodes (ids come in order)");
  compact_.push_back(std::move(compact));
  keep(id, std::move(built));
}

std::shared_ptr<const ReferenceScan> ReferenceStore::get(size_t id) const
{
  std::shared_ptr<const sensor::CompactScan> compact;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (id >= compact_.size())
      throw std::out_of_range("ReferenceStore: no node " + std::to_string(id) + " (" +
                              std::to_string(compact_.size()) + " added)");
    if (!compact_[id]) throw std::out_of_range("ReferenceStore: node " + std::to_string(id) + "'s scan was released");
    if (const auto it = built_.find(id); it != built_.end())
    {
      uses_.splice(uses_.begin(), uses_, it->second.use);
      return it->second.scan;
    }
    compact = compact_[id];
  }
  // Rebuilt without the lock: the other thread's lookups go on meanwhile.
  auto built = std::make_shared<const ReferenceScan>(sensor::expandScan(*compact), params_);
  std::lock_guard<std::mutex> lock(mutex_);
  if (const auto it = built_.find(id); it != built_.end()) return it->second.scan;  // built meanwhile
  keep(id, built);
  return built;
}

void ReferenceStore::keep(size_t id, std::shared_ptr<const ReferenceScan> built) const
{
  uses_.push_front(id);
  built_[id] = Built{std::move(built), uses_.begin()};
  while (built_.size() > built_kept_)
  {
    built_.erase(uses_.back());
    uses_.pop_back();
  }
}

void ReferenceStore::addReleased(size_t id)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (id != compact_.size())
    throw std::invalid_argument("ReferenceStore: node " + std::to_string(id) + " added after " +
                                std::to_string(compact_.size()) + " nodes (ids come in order)");
  compact_.push_back(nullptr);
}

void ReferenceStore::release(size_t id)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (id >= compact_.size())
    throw std::out_of_range("ReferenceStore: no node " + std::to_string(id) + " to release");
  compact_[id].reset();
  if (const auto it = built_.find(id); it != built_.end())
  {
    uses_.erase(it->second.use);
    built_.erase(it);
  }
}

size_t ReferenceStore::size() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return compact_.size();
}

size_t ReferenceStore::builtCount() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return built_.size();
}

size_t ReferenceStore::bytes() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  size_t b = 0;
  for (const auto& c : compact_)
    if (c) b += c->bytes();
  for (const auto& [id, built] : built_) b += referenceScanBytes(*built.scan);
  return b;
}

}  // namespace swslam::plicp
