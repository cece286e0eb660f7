// k-nearest-neighbour queries on a static point cloud, through nanoflann's kd-tree
// (header-only; Debian: libnanoflann-dev). Queries are const and thread-safe once built.
#ifndef NearestNeighbors_h
#define NearestNeighbors_h

#include <nanoflann.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace lsi
{

class PointCloudIndex
{
public:
  /// `xyz` holds 3 * count doubles and must outlive the index.
  PointCloudIndex(const double* xyz, std::size_t count)
    : Cloud{ xyz, count }
    , Tree(3, Cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16))
  {
    this->Tree.buildIndex();
  }

  /// The k points nearest to `query`, closest first: indices and squared distances.
  /// Returns how many were found (fewer than k only when the cloud is smaller).
  std::size_t Nearest(const double query[3], std::size_t k, std::uint32_t* indices,
    double* squaredDistances) const
  {
    return this->Tree.knnSearch(query, k, indices, squaredDistances);
  }

  /// Like Nearest, but only among points closer than sqrt(squaredBound): a good bound (from a
  /// query nearby) prunes most of the tree walk. Returns how many were found, possibly < k.
  std::size_t NearestWithin(const double query[3], std::size_t k, double squaredBound,
    std::uint32_t* indices, double* squaredDistances) const
  {
    nanoflann::KNNResultSet<double, std::uint32_t> result(k);
    result.init(indices, squaredDistances);
    squaredDistances[k - 1] = squaredBound; // the initial worst distance
    this->Tree.findNeighbors(result, query, nanoflann::SearchParams());
    return result.size();
  }

  std::size_t Size() const { return this->Cloud.Count; }

private:
  struct Adaptor
  {
    const double* Points;
    std::size_t Count;
    std::size_t kdtree_get_point_count() const { return this->Count; }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return this->Points[3 * i + d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const
    {
      return false;
    }
  };
  using Tree3D = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
    Adaptor, 3, std::uint32_t>;

  Adaptor Cloud;
  Tree3D Tree;
};

} // namespace lsi

#endif
