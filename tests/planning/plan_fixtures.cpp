// Out-of-line part of plan_fixtures.hpp (see there why).
#include "plan_fixtures.hpp"

#include "partition/partition.hpp"

namespace furrow::test {

RegionMap partition_of(const Part& part, int nu, int nv) {
  PartitionOptions o;
  o.grid = GridSize{nu, nv};
  return partition_part(part, o).map;
}

}  // namespace furrow::test
