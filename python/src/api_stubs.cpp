// The type stubs of the module's hand-written functions (recipes.cpp, scenery.cpp, module.cpp).
// Keep them beside any change to those functions' signatures; tests/python checks that every
// public name of the module has a stub.
#include <fmt/format.h>

#include "signatures.hpp"
#include "water/flow.hpp"

namespace sansui::python {

namespace {

/// The keys of [flow] a water function takes, as stub parameters (", channel_area: float = 1e6...").
std::string flow_keys() {
  std::string text;
  const water::FlowParams defaults;
  for (const auto& row : params::table_of<water::FlowParams>().rows) {
    if (row.key == "sea_level" || !row.exposed) continue;
    const params::Value value = row.get(defaults);
    text += fmt::format(", {}: {} = {}", row.key, python_type(row), params::format_number(std::get<double>(value)));
  }
  return text;
}

}  // namespace

std::string grid_stubs() {
  const std::string world_keys =
      "cell: Optional[float] = None, sea_level: Optional[float] = None, crs: Optional[str] = None, "
      "origin: Optional[Sequence[float]] = None, world: Optional[World] = None, progress: Progress = None";
  const std::string flow = flow_keys();
  return R"(class WorldWarning(UserWarning):
    """A call assumed a world (cell size, sea level) because an array it was given carried none."""

class Grid(np.ndarray[Any, np.dtype[Any]]):
    """A numpy array of a grid on its world (python/sansui/_grids.py): copies keep the world."""
    @property
    def cell(self) -> Optional[float]: ...
    @property
    def sea_level(self) -> Optional[float]: ...
    @property
    def crs(self) -> Optional[str]: ...
    @property
    def origin(self) -> Optional[Tuple[float, float]]: ...
    @property
    def kind(self) -> Optional[str]: ...
    @property
    def x(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def y(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def transform(self) -> Optional[Tuple[float, float, float, float, float, float]]: ...
    @property
    def bounds(self) -> Optional[Tuple[float, float, float, float]]: ...
    @property
    def world(self) -> Optional[World]: ...
    def to_xarray(self) -> Any: ...

def grid(array: ArrayLike, *, cell: Optional[float] = None, sea_level: Optional[float] = None, crs: Optional[str] = None,
         origin: Optional[Sequence[float]] = None, world: Optional[World] = None, kind: str = "heights") -> Grid:
    """Any 2-D array as a sansui.Grid on the world given (a DataArray or Grid brings its own)."""
    ...

def set_arrays(kind: Literal["numpy", "xarray"]) -> None:
    """What node functions return when no input is a DataArray: sansui.Grid or xarray.DataArray."""
    ...

def arrays() -> Literal["numpy", "xarray"]:
    """What set_arrays() chose."""
    ...

)" + fmt::format(R"(def flow_routing(heights: ArrayLike, *, {0}) -> Dict[str, Any]:
    """D8 routing across depressions: filled, receivers, stack, area, basins."""
    ...

def fill_depressions(heights: ArrayLike, *, epsilon: bool = False, {0}) -> Grid:
    """The DEM with every depression filled to its spill level (priority-flood)."""
    ...

def drainage_area(heights: ArrayLike, *, method: Literal["d8", "mfd"] = "d8"{1}, {0}) -> Grid:
    """Drainage area (flow accumulation) in m^2, D8 or multiple flow directions."""
    ...

def slope(heights: ArrayLike, *, {0}) -> Grid:
    """The slope of every sample in degrees."""
    ...

def surface_water(heights: ArrayLike, *{1}, {0}) -> Dict[str, Any]:
    """Rivers, lakes and wetness: grids and GeoJSON FeatureCollections."""
    ...

def rivers(heights: ArrayLike, *{1}, {0}) -> Dict[str, Any]:
    """The rivers as a GeoJSON FeatureCollection (one LineString per reach)."""
    ...

def lakes(heights: ArrayLike, *{1}, {0}) -> Dict[str, Any]:
    """The lakes as a GeoJSON FeatureCollection (one feature per lake)."""
    ...

)",
                 world_keys, flow);
}

std::string extra_stubs() {
  return R"(def set_threads(threads: int) -> None:
    """At most this many threads work in each call (0: all cores). Results never depend on it."""
    ...

def node_kinds() -> List[Dict[str, Any]]:
    """Every node kind: name, group, help, inputs [(name, type, optional)], output type."""
    ...

def threads() -> int:
    """The thread count set_threads() gave (0: all cores)."""
    ...

RecipeSource = Union[str, os.PathLike[str], Dict[str, Any], "Recipe", None]

class Recipe:
    """A whole recipe, as `sansui run` reads one: a scene file (.toml) or an output's sidecar
    (.json), a dict shaped like a scene file, another Recipe, or None for an empty one."""
    def __init__(self, source: RecipeSource = None) -> None: ...
    @staticmethod
    def from_toml(text: str, base_dir: Union[str, os.PathLike[str], None] = None) -> "Recipe": ...
    def node(self, id: str, kind: str, *inputs: str, **keys: Any) -> "Recipe":
        """A copy with one more node, e.g. node('eroded', 'erode', 'hills', stage='mature')."""
        ...
    def output(self, file: str, **keys: Any) -> "Recipe":
        """A copy with one more output, e.g. output('t.tif', node='eroded')."""
        ...
    @property
    def world(self) -> World: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def node_ids(self) -> List[str]: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_toml(self) -> str: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...
    def heights(self, node: Optional[str] = None, progress: Progress = None) -> Grid: ...
    def run(self, out_dir: Union[str, os.PathLike[str], None] = None, progress: Progress = None,
            cache: Union[str, os.PathLike[str], None] = None) -> List[str]: ...

def run(recipe: RecipeSource, out_dir: Union[str, os.PathLike[str], None] = None, progress: Progress = None,
        cache: Union[str, os.PathLike[str], None] = None) -> List[str]:
    """Runs a recipe as `sansui run` does and returns the files written."""
    ...

)" + scenery_stubs();
}

}  // namespace sansui::python
