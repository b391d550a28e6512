// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkAntialiasingTableCache.h
 * @brief  A process-wide cache of the tables that filters and passes share (internal header).
 *
 * vtkAntialiasingTableCache<Key, Table> hands out one table per key, built on first use and
 * shared by every caller that asks for it at the same time (vtkMLAAAreaTexture's area tables,
 * the CPU filter's quantised copies). A table lives while a caller holds it, and the `Keep` tables
 * asked for last (each of at most `KeepBytes`) also while nobody does, so that a filter made
 * afresh for each image finds its tables built. Nothing else stays: a long session that tries
 * every search length holds only the tables in use, not one per length it ever used. Thread-safe.
 *
 * Internal to MLAA::FiltersMLAA; not installed.
 */

#ifndef vtkAntialiasingTableCache_h
#define vtkAntialiasingTableCache_h

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

// The largest table that a cache keeps while nobody holds it, unless told otherwise: 1 MB.
constexpr std::size_t vtkAntialiasingTableCacheKeptBytes = std::size_t(1) << 20;

template <typename Key, typename Table>
class vtkAntialiasingTableCache
{
public:
  vtkAntialiasingTableCache(
    std::size_t keep, std::size_t keepBytes = vtkAntialiasingTableCacheKeptBytes)
    : Keep(keep)
    , KeepBytes(keepBytes)
  {
  }

  // The table of `key`, made by `build()` (returning a std::shared_ptr<const Table>) where no one
  // holds it.
  template <typename Build>
  std::shared_ptr<const Table> Get(const Key& key, Build build)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    std::shared_ptr<const Table> table = this->Tables[key].lock();
    if (!table)
    {
      table = build();
      this->Tables[key] = table;
      for (auto entry = this->Tables.begin(); entry != this->Tables.end();)
      {
        entry = entry->second.expired() ? this->Tables.erase(entry) : std::next(entry);
      }
    }
    auto& recent = this->Recent;
    recent.erase(std::remove(recent.begin(), recent.end(), table), recent.end());
    if (table->size() * sizeof(typename Table::value_type) <= this->KeepBytes)
    {
      recent.insert(recent.begin(), table);
      if (recent.size() > this->Keep)
      {
        recent.pop_back();
      }
    }
    return table;
  }

private:
  const std::size_t Keep;
  const std::size_t KeepBytes;
  std::mutex Mutex;
  std::map<Key, std::weak_ptr<const Table>> Tables;
  std::vector<std::shared_ptr<const Table>> Recent; // the last asked for first
};

#endif
