"""The type stubs, generated from the parameter tables, cover the module and parse."""
import ast
import pathlib

import sansui


def stub_tree():
    path = pathlib.Path(sansui.__file__).with_name("__init__.pyi")
    return ast.parse(path.read_text()), path.read_text()


def test_every_public_name_has_a_stub():
    tree, _ = stub_tree()
    stubbed = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    stubbed |= {t.id for node in tree.body if isinstance(node, (ast.Assign, ast.AnnAssign))
                for t in (node.targets if isinstance(node, ast.Assign) else [node.target]) if isinstance(t, ast.Name)}
    public = {name for name in dir(sansui) if not name.startswith("_")}
    assert public - stubbed == set()


def test_node_stubs_carry_the_table_s_keys_types_and_defaults():
    tree, text = stub_tree()
    midpoint = next(node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == "midpoint")
    keys = {arg.arg: arg for arg in midpoint.args.kwonlyargs}
    assert ast.unparse(keys["hurst"].annotation) == "float"
    assert ast.unparse(keys["seed"].annotation) == "int"
    defaults = dict(zip([a.arg for a in midpoint.args.kwonlyargs], midpoint.args.kw_defaults))
    assert ast.literal_eval(defaults["hurst"]) == 0.7
    erode = next(node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == "erode")
    assert [a.arg for a in erode.args.args] == ["heights", "mask"]  # positional or by name, as inspect.signature says
    stage = next(a for a in erode.args.kwonlyargs if a.arg == "stage")
    assert "Literal[" in ast.unparse(stage.annotation) and "'mature'" in ast.unparse(stage.annotation)
    assert ast.get_docstring(midpoint).startswith("midpoint(")
