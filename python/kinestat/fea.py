"""FEA link stiffness (C++ kinestat::fea): tetrahedral meshes, the 6x6 stiffness of a link clamped at
one end and loaded through a reference body at the other, and the on-disk result cache."""
from typing import NamedTuple, Optional, Union

from ._kinestat import InputError, Material
from ._kinestat.fea import *  # noqa: F401,F403
from ._kinestat.fea import (LinkStiffness, LinkStiffnessOptions, MeshingOptions, ReferenceModel, Region, TetMesh,
                            check_surface_file, default_mesh_size, link_stiffness, link_stiffness_cache_key,
                            load_cached_link_stiffness, mesh_surface_file, parse_material, parse_region,
                            store_cached_link_stiffness, surface_mesh_identity)


class LinkStiffnessRun(NamedTuple):
    """What link_stiffness_from_file found: the result, the mesh (None when it came from the cache)
    and whether it came from the cache."""
    result: LinkStiffness
    mesh: Optional[TetMesh]
    from_cache: bool


def link_stiffness_from_file(path: str, *, clamp: Union[str, Region], reference: Union[str, Region],
                             material: Union[str, Material] = "steel", unit: str = "mm",
                             size: Optional[float] = None, quadratic: bool = True,
                             reference_model: ReferenceModel = ReferenceModel.RIGID_COUPLING,
                             stiff_body_ratio: float = 1e4, reference_point=None, keep_fields: bool = False,
                             cache: Optional[str] = None) -> LinkStiffnessRun:
    """The 6x6 stiffness of a link from its surface file, as `kinestat link-stiffness` computes it.

    path: closed triangle surface (STL, OFF, OBJ, PLY) in `unit` ("mm" or "m").
    clamp, reference: regions in the CLI's syntax and the file's unit ("x=0", "plane:PX,PY,PZ,NX,NY,NZ",
        "box:X0,Y0,Z0,X1,Y1,Z1") or Region objects (m).
    material: "steel", "aluminium", "E=PA,nu=V" or a Material.
    size: tetrahedron size in the file's unit (None: 1/20 of the part's largest extent).
    reference_point: the point whose motion is reported, in the file's unit (None: the reference nodes' centre).
    keep_fields: keep the displacement and von Mises fields (for io.write_link_vtu_files); a cached result has none.
    cache: a folder for the result cache (the key covers the file's bytes, the meshing, the material and options).

    Raises InputError with the CLI's messages. Meshing and the solve release the GIL.
    """
    if unit not in ("mm", "m"):
        raise InputError(f"unit '{unit}': use mm or m")
    scale = 1e-3 if unit == "mm" else 1.0
    if isinstance(material, str):
        material = parse_material(material, "material " + material)
    options = LinkStiffnessOptions()
    options.clamp = parse_region(clamp, scale, "clamp " + clamp) if isinstance(clamp, str) else clamp
    options.reference = (parse_region(reference, scale, "reference " + reference)
                         if isinstance(reference, str) else reference)
    options.reference_model = reference_model
    options.stiff_body_ratio = stiff_body_ratio
    if reference_point is not None:
        options.reference_point = [scale * float(x) for x in reference_point]
    options.keep_fields = keep_fields

    surface = check_surface_file(path)
    meshing = MeshingOptions()
    meshing.unit_scale = scale
    meshing.quadratic = quadratic
    meshing.size = size * scale if size is not None else default_mesh_size(surface, scale)
    key = None
    if cache is not None:
        key = link_stiffness_cache_key(surface_mesh_identity(path, meshing), material, options)
        if not keep_fields:
            cached = load_cached_link_stiffness(cache, key)
            if cached is not None:
                return LinkStiffnessRun(cached, None, True)
    mesh = mesh_surface_file(path, meshing)
    result = link_stiffness(mesh, material, options)
    if key is not None:
        store_cached_link_stiffness(cache, key, result)
    return LinkStiffnessRun(result, mesh, False)
