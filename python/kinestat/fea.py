"""FEA link stiffness (C++ kinestat::fea): tetrahedral meshes, the 6x6 stiffness of a link clamped at
one end and loaded through a reference body at the other, and the on-disk result cache."""
from typing import Optional, Sequence, Union

from ._kinestat import InputError, Material
from ._kinestat.fea import *  # noqa: F401,F403
from ._kinestat.fea import (LinkStiffnessRequest, LinkStiffnessRun, ReferenceModel, Region, compute_link_stiffness,
                            parse_material, parse_region)


def link_stiffness_request(path: str, *, clamp: Union[str, Region], reference: Union[str, Region],
                           material: Union[str, Material] = "steel", unit: str = "mm", size: Optional[float] = None,
                           quadratic: bool = True, reference_model: ReferenceModel = ReferenceModel.RIGID_COUPLING,
                           stiff_body_ratio: float = 1e4, reference_point: Optional[Sequence[float]] = None,
                           keep_fields: bool = False, cache: Optional[str] = None,
                           modes: int = 0) -> LinkStiffnessRequest:
    """The LinkStiffnessRequest of `kinestat link-stiffness` with these options (link_stiffness_from_file
    describes them); for compute_link_stiffness and link_stiffness_convergence."""
    if unit not in ("mm", "m"):
        raise InputError(f"unit '{unit}': use mm or m")
    scale = 1e-3 if unit == "mm" else 1.0
    request = LinkStiffnessRequest()
    request.mesh_file = path
    request.unit_scale = scale
    request.mesh_size = 0.0 if size is None else size * scale
    request.quadratic = quadratic
    # Material strings in SI (Pa), as the library's parse_material takes them by default.
    request.material = parse_material(material, "material " + material) if isinstance(material, str) else material
    options = request.options
    options.clamp = parse_region(clamp, scale, "clamp " + clamp) if isinstance(clamp, str) else clamp
    options.reference = (parse_region(reference, scale, "reference " + reference)
                         if isinstance(reference, str) else reference)
    options.reference_model = reference_model
    options.stiff_body_ratio = stiff_body_ratio
    if reference_point is not None:
        options.reference_point = [scale * float(x) for x in reference_point]
    options.keep_fields = keep_fields
    options.modes = modes
    request.cache_dir = cache or ""
    return request


def link_stiffness_from_file(path: str, *, clamp: Union[str, Region], reference: Union[str, Region],
                             material: Union[str, Material] = "steel", unit: str = "mm",
                             size: Optional[float] = None, quadratic: bool = True,
                             reference_model: ReferenceModel = ReferenceModel.RIGID_COUPLING,
                             stiff_body_ratio: float = 1e4, reference_point: Optional[Sequence[float]] = None,
                             keep_fields: bool = False, cache: Optional[str] = None,
                             modes: int = 0) -> LinkStiffnessRun:
    """The 6x6 stiffness of a link from its surface file, as `kinestat link-stiffness` computes it
    (compute_link_stiffness: the library's one path from a surface file to the 6x6).

    path: closed triangle surface (STL, OFF, OBJ, PLY) in `unit` ("mm" or "m").
    clamp, reference: regions in the CLI's syntax and the file's unit ("x=0", "plane:PX,PY,PZ,NX,NY,NZ",
        "box:X0,Y0,Z0,X1,Y1,Z1") or Region objects (m).
    material: "steel" (7850 kg/m^3), "aluminium" (2700 kg/m^3), "E=PA,nu=V[,rho=KG_M3]" (Pa, kg/m^3) or a Material.
    size: tetrahedron size in the file's unit (None: 1/20 of the part's largest extent).
    reference_point: the point whose motion is reported, in the file's unit (None: the reference nodes' centre).
    keep_fields: keep the mesh and the displacement and von Mises fields (for io.write_link_vtu_files); such a
        result is always computed, never read from the cache.
    modes: also the lowest `modes` natural frequencies (count, 1 to 100; 0: none) of the clamped link with a
        massless reference body, in .result.modes (LinkMode: frequency Hz, mass-normalized shapes with keep_fields);
        needs the material's density ("steel", "aluminium" or "E=PA,nu=V,rho=KG_M3"); always computed.
    cache: a folder for the result cache (the key covers the file's bytes, the meshing, the material and options);
        a damaged entry is recomputed with a RuntimeWarning saying why (also in .warnings).

    Returns a LinkStiffnessRun: .result (LinkStiffness), .mesh (None unless keep_fields), .from_cache, .report.
    Raises InputError with the CLI's messages. Meshing and the solve release the GIL.
    """
    return compute_link_stiffness(link_stiffness_request(
        path, clamp=clamp, reference=reference, material=material, unit=unit, size=size, quadratic=quadratic,
        reference_model=reference_model, stiff_body_ratio=stiff_body_ratio, reference_point=reference_point,
        keep_fields=keep_fields, cache=cache, modes=modes))
