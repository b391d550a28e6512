# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Morphological antialiasing (MLAA) and DLAA for VTK, from Python.

DLAA here is DLAA (Andreev 2011, directionally localized antialiasing), which blurs each edge
along its own direction; not the learned method of the same initials.

The classes are VTK's own Python wrappings of the C++ classes (the same names and methods;
``help(vtkmlaa.vtkImageMLAA)`` shows their documentation):

- ``vtkImageMLAA``, ``vtkImageDLAA``: CPU image filters for any ``vtkImageData``;
- ``vtkOpenGLMLAAPass``, ``vtkOpenGLDLAAPass``: render passes for a ``vtkRenderer``;
- ``vtkMLAAOptions``, ``vtkDLAAOptions``: the settings the filters and the passes share;
- ``vtkMLAAAreaTexture``, ``vtkMLAATopology`` and the base classes
  ``vtkImageAntialiasingAlgorithm``, ``vtkOpenGLAntialiasingPass``.

Two conveniences for the common cases:

- ``enable(renderer, method="mlaa", preset=None, **options)`` installs a pass on a renderer
  or on a PyVista plotter (``vtkmlaa.enable(plotter)``, which PyVista's own effects may come
  before); ``disable(renderer)`` removes it; ``render_still(renderer)`` renders a temporal pass
  until its still has converged;
- ``antialias_array(array, method="mlaa", preset=None, **options)`` antialiases a numpy array.
"""

import warnings

# VTK's modules first: the wrapped classes derive from theirs, and importing
# vtkRenderingOpenGL2 registers the OpenGL overrides of the rendering classes (without it,
# vtkRenderWindow() would not make an OpenGL window, and the passes would have nothing to run in).
from vtkmodules import vtkCommonCore as _vtkCommonCore
from vtkmodules import vtkCommonDataModel as _vtkCommonDataModel
from vtkmodules import vtkRenderingCore as _vtkRenderingCore
from vtkmodules import vtkRenderingOpenGL2 as _vtkRenderingOpenGL2

from . import vtkFiltersMLAA
from . import vtkRenderingMLAA
# The classes the functions below use (every class is exported below).
from .vtkFiltersMLAA import vtkDLAAOptions, vtkImageDLAA, vtkImageMLAA, vtkMLAAOptions
from .vtkRenderingMLAA import vtkOpenGLAntialiasingPass, vtkOpenGLDLAAPass, vtkOpenGLMLAAPass

__all__ = []


def _export(module):
    """Every class of an extension module as an attribute of the package, and in __all__."""
    for name in dir(module):
        if name.startswith("vtk"):
            globals()[name] = getattr(module, name)
            __all__.append(name)


_export(vtkFiltersMLAA)
_export(vtkRenderingMLAA)
del _export

__all__ += ["enable", "disable", "antialias_array", "METHODS", "PRESETS"]

#: The methods that enable() and antialias_array() accept.
METHODS = ("mlaa", "dlaa")

#: The names of the MLAA presets, as vtkMLAAOptions spells them (GetPresetAsString).
PRESETS = tuple(
    vtkMLAAOptions.GetPresetAsString(preset)
    for preset in (vtkMLAAOptions.LOW, vtkMLAAOptions.MEDIUM, vtkMLAAOptions.HIGH,
                   vtkMLAAOptions.ULTRA, vtkMLAAOptions.MAX))


def _method_classes(method):
    """The (filter, pass, options) classes of a method name."""
    key = str(method).lower()
    if key == "mlaa":
        return vtkImageMLAA, vtkOpenGLMLAAPass, vtkMLAAOptions
    if key == "dlaa":
        return vtkImageDLAA, vtkOpenGLDLAAPass, vtkDLAAOptions
    raise ValueError("unknown antialiasing method %r: expected one of %s"
                     % (method, ", ".join(METHODS)))


def _camel_case(name):
    """'max_search_steps' -> 'MaxSearchSteps'; a name already in CamelCase is kept."""
    if "_" not in name and name[:1].isupper():
        return name
    return "".join(part[:1].upper() + part[1:] for part in name.split("_") if part)


def _settable(obj, name):
    """Whether obj has a Set<name>/Get<name> pair (a setting), as VTK's macros make them."""
    return callable(getattr(obj, "Set" + name, None)) and \
        callable(getattr(obj, "Get" + name, None))


def _setting_names(obj, exclude=()):
    """The settings of a VTK object, for error messages."""
    names = sorted(
        attr[3:] for attr in dir(obj)
        if attr.startswith("Set") and _settable(obj, attr[3:]) and attr[3:] not in exclude)
    return names


# Settings that are not options: the preset (an argument of its own), the objects a pass or a
# filter is built from, and what every vtkObject has (Debug, GlobalWarningDisplay, ...).
_NOT_OPTIONS = frozenset(["Preset", "Options", "DelegatePass"] + _setting_names(
    _vtkCommonCore.vtkObject()))


def _apply_options(options, targets, method):
    """Set each keyword option on the first of targets that has it. Values of enumerated
    settings may be given by name (edge_detection="luma"): the options class parses them with
    its own Get<Name>FromString, so the names are those of the C++ classes and the mlaa tool."""
    for key, value in options.items():
        name = _camel_case(key)
        for target in targets:
            if name in _NOT_OPTIONS or not _settable(target, name):
                continue
            if isinstance(value, str):
                parse = getattr(target, "Get%sFromString" % name, None)
                if parse is None:
                    raise ValueError("option %r takes a number, not %r" % (key, value))
                parsed = parse(value)
                if parsed < 0:
                    raise ValueError("unknown value %r for option %r" % (value, key))
                value = parsed
            setter = getattr(target, "Set" + name)
            setter(value)
            got = getattr(target, "Get" + name)()
            if isinstance(value, (int, float)) and not isinstance(value, bool) and \
                    got != value:
                raise ValueError("option %r: %r is out of range (clamped to %r)"
                                 % (key, value, got))
            break
        else:
            known = []
            for target in targets:
                known += _setting_names(target, exclude=_NOT_OPTIONS)
            raise ValueError("unknown %s option %r; the options are: %s"
                             % (method, key, ", ".join(sorted(set(known)))))


def _configure(options_object, method, preset, options, extra_targets=()):
    """Apply a preset name and keyword options to an options object (and, for a pass, to the
    pass's own settings such as KeepAlpha and AntialiasOverlays)."""
    if str(method).lower() == "mlaa":
        name = "high" if preset is None else preset
        value = vtkMLAAOptions.GetPresetFromString(str(name).lower())
        if value < 0:
            raise ValueError("unknown MLAA preset %r: expected one of %s"
                             % (preset, ", ".join(PRESETS)))
        options_object.SetPreset(value)
    elif preset is not None:
        raise ValueError("DLAA has no presets (got preset=%r); set its options instead"
                         % (preset,))
    _apply_options(options, (options_object,) + tuple(extra_targets), method)


def _plotter_renderers(target, every_renderer=False):
    """(renderers, plotter): a vtkRenderer alone, or a PyVista-style plotter's renderers (its
    active one, or with every_renderer all of them) and the plotter itself."""
    if isinstance(target, _vtkRenderingCore.vtkRenderer):
        return [target], None
    renderer = getattr(target, "renderer", None)
    if isinstance(renderer, _vtkRenderingCore.vtkRenderer):
        renderers = [renderer]
        if every_renderer:
            renderers = [r for r in getattr(target, "renderers", renderers)
                         if isinstance(r, _vtkRenderingCore.vtkRenderer)] or renderers
        return renderers, target
    raise TypeError("expected a vtkRenderer or a PyVista Plotter (an object with a .renderer), "
                    "not %s" % type(target).__name__)


def _is_plain_steps(render_pass):
    """Whether a pass is the vtkRenderStepsPass enable() gives a pass of ours by default."""
    return render_pass is not None and render_pass.GetClassName() == "vtkRenderStepsPass"


def _foreign_pass(renderer):
    """The render pass another library installed on the renderer (PyVista's effects: eye-dome
    lighting, SSAO, shadows, SSAA, blur, depth of field), or None: the renderer's pass, or the
    delegate of the pass of ours that wraps it; None when there is no such pass."""
    current = renderer.GetPass()
    if isinstance(current, vtkOpenGLAntialiasingPass):
        current = current.GetDelegatePass()
    if current is None or _is_plain_steps(current):
        return None
    return current


def _pass_chain(render_pass, depth=0):
    """The class names of a pass and of the passes it runs (its delegate, the passes of a
    sequence), outermost first (for messages)."""
    if render_pass is None or depth > 8:
        return []
    names = [render_pass.GetClassName()]
    get_delegate = getattr(render_pass, "GetDelegatePass", None)
    if get_delegate is not None:
        names += _pass_chain(get_delegate(), depth + 1)
    get_passes = getattr(render_pass, "GetPasses", None)
    passes = get_passes() if get_passes is not None else None
    if passes is not None:
        passes.InitTraversal()
        for _ in range(passes.GetNumberOfItems()):
            names += _pass_chain(passes.GetNextRenderPass(), depth + 1)
    return names


def _render_plotter(plotter):
    """Have a plotter draw again with its renderers' new passes, so that its next screenshot()
    shows them: PyVista renders lazily and would return the image it already has."""
    render = getattr(plotter, "render", None)
    window = getattr(plotter, "render_window", None)
    if callable(render) and window is not None:
        render()


def enable(renderer, method="mlaa", preset=None, temporal=False, multisamples=0,
           every_renderer=False, **options):
    """Antialias everything a renderer draws, with a render pass; returns the pass.

    renderer: a vtkRenderer, or a PyVista Plotter (pyvista.Plotter, or any object whose
    .renderer is a vtkRenderer): its active renderer, or with every_renderer=True each of its
    renderers (subplots; the pass of the active one is returned). With a plotter, the plotter is
    rendered again, so that its next screenshot() is antialiased.

    Calling enable() again replaces the renderer's pass: the old pass's graphics resources are
    released first, in its window's context.

    A pass that PyVista (or another library) installed for its own effects, such as eye-dome
    lighting, SSAO, shadows or SSAA (enable_eye_dome_lighting(), enable_ssao(),
    enable_shadows(), enable_anti_aliasing("ssaa")), becomes the antialiasing pass's delegate:
    the effect is drawn as before, then antialiased. That needs the single-sample mode:
    temporal=True and multisamples > 0 raise ValueError there, naming the pass, since their
    jittered and multisampled renders would bypass the effect. Enable such effects before
    vtkmlaa (an effect enabled after it installs its own pass in its place; enable() again puts
    the antialiasing back on top). The overlays (text, scalar bars) are then antialiased too.

    Installs a vtkRenderStepsPass (VTK's usual steps: lights, opaque and translucent geometry,
    volumes, overlays) wrapped in a vtkOpenGLMLAAPass (method="mlaa") or vtkOpenGLDLAAPass
    (method="dlaa") as the renderer's pass, and turns multisampling off on the renderer's
    render window (the pass replaces it). Call it once the renderer is in its window; a
    renderer without a window gets the pass, and its window's multisampling must then be
    turned off by hand (SetMultiSamples(0)).

    Translucent geometry and volumes are drawn as the renderer draws them without the pass:
    order-independent translucency by default, (dual) depth peeling when the renderer's
    UseDepthPeeling is on (with its MaximumNumberOfPeels, OcclusionRatio and
    UseDepthPeelingForVolumes), and renderer.GetLastRenderingUsedDepthPeeling() reports it.

    preset: for MLAA, one of "low", "medium", "high" (the default), "ultra" and "max" (ultra with
    reconstruction, for sub-pixel lines and points); DLAA has none.
    options: settings of the options object (vtkMLAAOptions or vtkDLAAOptions) or of the pass,
    by their VTK name in snake_case or CamelCase, e.g. threshold=0.05, max_search_steps=8,
    edge_detection="luma", keep_alpha=True, antialias_overlays=True; they are applied after
    the preset. Unknown methods, presets and options raise ValueError.

    temporal: temporal antialiasing (SetTemporal on the pass): each render is jittered by a
    sub-pixel offset and blended with a history, so that a still scene converges to the
    supersampled picture over successive renders and a moving camera flickers less. Take a
    screenshot after render_still(renderer). Default False.
    multisamples: 0 (the default) antialiases the single-sample render; 2, 4 or 8 renders the
    scene with that many samples per pixel, runs the method on each sample set and averages them
    (SetMultiSamples: multisampling's sub-pixel coverage with the method's gradients, at about
    the method's cost once per sample). Where the driver does not offer the count, the pass uses
    the nearest one it offers and warns once (pass.GetRenderedMultiSamples() tells which). The
    window's own multisampling is turned off either way. An integer 0 to 16, else ValueError.
    With temporal=True too, the renders that the history takes a frame from (the first, and
    those of a moving camera) render the samples and blend their antialiased resolve; a still
    accumulation renders one sample per pixel, as without samples. Every
    sample is shaded at its own position, so that texture and colour edges are sampled too;
    sample_shading=False (an option of the pass) shades once per pixel, as multisampling does.

    With a PyVista plotter: vtkmlaa.enable(plotter); plotter.screenshot(...).
    """
    renderers, plotter = _plotter_renderers(renderer, every_renderer)
    _, pass_class, _ = _method_classes(method)
    if isinstance(multisamples, bool) or not isinstance(multisamples, int) or \
            not 0 <= multisamples <= 16:
        raise ValueError("multisamples must be an integer from 0 to 16 (0: single-sample), "
                         "got %r" % (multisamples,))
    # Every check before any renderer changes: an error leaves them all as they were.
    for target in renderers:
        foreign = _foreign_pass(target)
        if foreign is not None and (temporal or multisamples):
            raise ValueError(
                "vtkmlaa.enable(): the renderer already has another render pass (%s, an effect "
                "such as PyVista's eye-dome lighting, SSAO, shadows or SSAA); %s cannot wrap it. "
                "Use the single-sample mode with it, or disable the effect first"
                % (" -> ".join(_pass_chain(foreign)),
                   "temporal=True" if temporal else "multisamples=%d" % multisamples))
    passes = []
    for target in renderers:
        aa_pass = pass_class()
        _configure(aa_pass.GetOptions(), method, preset, options, extra_targets=(aa_pass,))
        aa_pass.SetTemporal(bool(temporal))
        aa_pass.SetMultiSamples(multisamples)
        disable(target)  # releases a pass of ours that enable() installed before
        foreign = _foreign_pass(target)
        aa_pass.SetDelegatePass(foreign if foreign is not None
                                else _vtkRenderingOpenGL2.vtkRenderStepsPass())
        target.SetPass(aa_pass)
        window = target.GetRenderWindow()
        if window is not None:
            window.SetMultiSamples(0)
        elif plotter is None:
            warnings.warn("vtkmlaa.enable(): the renderer has no render window yet; call "
                          "SetMultiSamples(0) on the window it goes into (or call enable() "
                          "after AddRenderer)", stacklevel=2)
        passes.append(aa_pass)
    if plotter is not None:
        _render_plotter(plotter)
    return passes[0]


def render_still(renderer, frames=None):
    """Render the renderer's window until its antialiasing pass holds a converged still; returns
    the number of renders. renderer: a vtkRenderer or a PyVista plotter (its active renderer;
    then plotter.screenshot() shows the converged picture).

    With a temporal pass (enable(..., temporal=True)), the window is rendered until the pass has
    averaged `frames` renders of the unchanged scene (vtkOpenGLAntialiasingPass.RenderConverged;
    frames: its ConvergedFrames, 16 unless set). Without a pass, or with a pass that is not
    temporal, the window is rendered once. A screenshot taken next (vtkWindowToImageFilter renders
    once more) shows the converged picture.
    """
    renderers, _ = _plotter_renderers(renderer)
    renderer = renderers[0]
    window = renderer.GetRenderWindow()
    if window is None:
        raise ValueError("render_still(): the renderer is in no render window")
    aa_pass = renderer.GetPass()
    if not isinstance(aa_pass, vtkOpenGLAntialiasingPass) or not aa_pass.GetTemporal():
        window.Render()
        return 1
    if frames is not None:
        if int(frames) < 1:
            raise ValueError("render_still(): frames must be at least 1, not %r" % (frames,))
        aa_pass.SetConvergedFrames(int(frames))
    return aa_pass.RenderConverged(window)


def disable(renderer, every_renderer=False):
    """Remove the antialiasing pass that enable() installed (any vtkOpenGLAntialiasingPass) from
    a renderer, or from a PyVista plotter's active renderer (every_renderer: all of them), and
    release its graphics resources; returns True if there was one. A pass it wrapped (a PyVista
    effect) becomes the renderer's pass again. Multisampling stays off. A plotter is rendered
    again, so that its next screenshot() is without the pass."""
    renderers, plotter = _plotter_renderers(renderer, every_renderer)
    removed = False
    for target in renderers:
        current = target.GetPass()
        if not isinstance(current, vtkOpenGLAntialiasingPass):
            continue
        delegate = current.GetDelegatePass()
        window = target.GetRenderWindow()
        if window is not None:
            # The pass's textures and shaders belong to the window's context: free them now,
            # while the pass is still known (the renderer frees only its current pass's).
            current.ReleaseGraphicsResources(window)
        target.SetPass(None if delegate is None or _is_plain_steps(delegate) else delegate)
        removed = True
    if removed and plotter is not None:
        _render_plotter(plotter)
    return removed


def antialias_array(array, method="mlaa", preset=None, **options):
    """Antialias an image held in a numpy array; returns a new array of the same shape and type.

    array: shape (rows, columns) for one component, or (rows, columns, components) with 1 to 4
    components (grey, grey + alpha, RGB, RGBA), any numeric type. Row i is image row y = i (the
    result has the same layout). Integer types are normalised by their whole range, floating
    point by [0, 1] (value_range=(lo, hi) sets another range, as SetValueRange does).
    preset and options: as for enable(). Errors of the filter raise RuntimeError.
    """
    import numpy
    from vtkmodules.util import numpy_support

    filter_class, _, _ = _method_classes(method)
    data = numpy.asarray(array)
    if data.ndim == 2:
        rows, columns, components = data.shape[0], data.shape[1], 1
    elif data.ndim == 3:
        rows, columns, components = data.shape
    else:
        raise ValueError("expected an array of shape (rows, columns[, components]), got %s"
                         % (data.shape,))
    if not 1 <= components <= 4:
        raise ValueError("expected 1 to 4 components, got %d" % components)
    if data.dtype.kind not in "biuf":
        raise ValueError("expected a numeric array, got dtype %s" % data.dtype)
    if data.dtype.kind == "b":
        raise ValueError("boolean arrays are not images; convert to uint8 first")

    value_range = options.pop("value_range", None)
    image = _vtkCommonDataModel.vtkImageData()
    image.SetDimensions(columns, rows, 1)
    flat = numpy.ascontiguousarray(data).reshape(rows * columns, components)
    scalars = numpy_support.numpy_to_vtk(flat, deep=True)
    scalars.SetName("pixels")
    image.GetPointData().SetScalars(scalars)

    aa = filter_class()
    _configure(aa.GetOptions(), method, preset, options)
    if value_range is not None:
        lo, hi = value_range
        aa.SetValueRange(float(lo), float(hi))
    errors = []

    def on_error(caller, event, message=None):
        # "ERROR: In FILE, line N\nvtkImageMLAA (0x...): what went wrong": keep what went wrong.
        lines = [line for line in str(message).splitlines() if line.strip()]
        text = lines[-1] if lines else str(message)
        errors.append(text.split("): ", 1)[-1].strip())
    on_error.CallDataType = _vtkCommonCore.VTK_STRING
    aa.AddObserver("ErrorEvent", on_error)
    # The executive then reports that the request failed; the filter's message says why, and
    # the exception carries it, so the executive's is kept off the console.
    aa.GetExecutive().AddObserver("ErrorEvent", lambda caller, event: None)
    aa.SetInputData(image)
    aa.Update()

    out = aa.GetOutput().GetPointData().GetScalars()
    if errors or out is None:
        raise RuntimeError("%s failed: %s" % (filter_class.__name__,
                                              "; ".join(str(e) for e in errors) or "no output"))
    result = numpy_support.vtk_to_numpy(out).reshape(data.shape).astype(data.dtype, copy=True)
    return result
