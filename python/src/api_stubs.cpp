// The type stubs of the module's hand-written functions (recipes.cpp, scenery.cpp, module.cpp).
// Keep them beside any change to those functions' signatures; tests/python checks that every
// public name of the module has a stub.
#include "signatures.hpp"

namespace sansui::python {

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
    def heights(self, node: Optional[str] = None, progress: Progress = None) -> Array: ...
    def run(self, out_dir: Union[str, os.PathLike[str], None] = None, progress: Progress = None,
            cache: Union[str, os.PathLike[str], None] = None) -> List[str]: ...

def run(recipe: RecipeSource, out_dir: Union[str, os.PathLike[str], None] = None, progress: Progress = None,
        cache: Union[str, os.PathLike[str], None] = None) -> List[str]:
    """Runs a recipe as `sansui run` does and returns the files written."""
    ...

)" + scenery_stubs();
}

}  // namespace sansui::python
