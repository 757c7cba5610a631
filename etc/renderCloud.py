"""Renders a sphCast case's particle clouds at one written time to a PNG, with ParaView.

Run with ParaView's Python (5.11 or later: Debian 12's, or ParaView's own binaries):

    pvpython etc/renderCloud.py CASE.pvd --field T --time last \\
        --clip-origin 0 0 0 --clip-normal 0 1 0 --output view.png

Every cloud of the chosen time is shown (metal and mold alike) as spheres of the particle
spacing (the clouds' 'spacing' attribute, else an estimate from the bounds), coloured by the
field; a cloud without the field is drawn in solid grey. A clip plane keeps the half behind
its normal and the camera then looks at the cut face along -normal. The legend gives the
field's name and unit, the title the case and the time. `--help` lists every option.
"""

import argparse
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

# Units of the fields sphCast writes (doc/physics.md); a field not listed gets no unit.
UNITS = {
    "T": "K", "heldTemperature": "K", "p": "Pa", "U": "m/s", "acceleration": "m/s^2",
    "rho": "kg/m^3", "restDensity": "kg/m^3", "densityRate": "kg/m^3/s", "mass": "kg",
    "volume": "m^3", "u": "J/kg", "viscosity": "Pa s", "conductivity": "W/m/K",
    "wallDistance": "m", "liquidusTime": "s", "solidusTime": "s", "fillTime": "s",
    "coolingRate": "K/s",
}
# Fields with a natural fixed colour range (the data's own range is used for the others).
FIXED_RANGES = {"solidFraction": (0.0, 1.0), "frozen": (0.0, 1.0)}
GREY = [0.62, 0.62, 0.62]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="pvpython etc/renderCloud.py",
        description="Renders a sphCast case (its <case>.pvd) at one written time to a PNG.")
    parser.add_argument("pvd", help="the case's <case>.pvd (or the case folder holding one)")
    parser.add_argument("--field", default="T",
                        help="point field to colour by (default T); vectors by magnitude")
    parser.add_argument("--time", default="last",
                        help="'first', 'last' (default) or a time in s (the nearest written)")
    parser.add_argument("--clouds", nargs="+", metavar="NAME",
                        help="only these clouds (default: every cloud of the time)")
    parser.add_argument("--clip-origin", nargs=3, type=float, metavar=("X", "Y", "Z"),
                        help="a point of the clip plane (default 0 0 0 when a normal is given)")
    parser.add_argument("--clip-normal", nargs=3, type=float, metavar=("NX", "NY", "NZ"),
                        help="the clip plane's normal: the half it points into is removed")
    parser.add_argument("--range", nargs=2, type=float, metavar=("MIN", "MAX"),
                        help="colour range (default: [0, 1] for solidFraction and frozen, "
                             "else the range over the shown particles)")
    parser.add_argument("--colormap", default="Cool to Warm",
                        help="a ParaView colour-map preset (default 'Cool to Warm')")
    parser.add_argument("--view-direction", nargs=3, type=float, metavar=("DX", "DY", "DZ"),
                        help="direction the camera looks in (default: -normal with a clip, "
                             "the thin axis for a flat cloud, else from the front-right-above)")
    parser.add_argument("--view-up", nargs=3, type=float, metavar=("UX", "UY", "UZ"),
                        help="the camera's up direction (default +z, or +y looking along z)")
    parser.add_argument("--perspective", action="store_true",
                        help="perspective projection (default: parallel)")
    parser.add_argument("--zoom", type=float, default=1.0,
                        help="magnification after fitting the clouds into the image (default 1)")
    parser.add_argument("--point-radius", type=float, metavar="R",
                        help="sphere radius in m (default: half the cloud's particle spacing)")
    parser.add_argument("--size", nargs=2, type=int, default=[1200, 900],
                        metavar=("WIDTH", "HEIGHT"), help="image size in pixels (default 1200 900)")
    parser.add_argument("--title", help="title text (default: '<case>   t = <time> s')")
    parser.add_argument("--output", "-o", help="PNG to write (default: <case>_<field>_<time>.png "
                        "beside the .pvd)")
    args = parser.parse_args(argv)
    if args.clip_origin and not args.clip_normal:
        parser.error("--clip-origin needs --clip-normal")
    if args.clip_normal and vector_norm(args.clip_normal) == 0:
        parser.error("--clip-normal must not be zero")
    if args.view_direction and vector_norm(args.view_direction) == 0:
        parser.error("--view-direction must not be zero")
    if args.range and not args.range[0] < args.range[1]:
        parser.error("--range needs MIN < MAX")
    return args


def vector_norm(v):
    return math.sqrt(sum(c * c for c in v))


def normalized(v):
    n = vector_norm(v)
    return [c / n for c in v]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def fail(message):
    sys.stderr.write("renderCloud: error: " + message + "\n")
    sys.exit(1)


def read_pvd(pvd):
    """{time: [(timeName, cloud, file)]} from the index sphCast writes."""
    try:
        root = ElementTree.parse(pvd).getroot()
    except (OSError, ElementTree.ParseError) as error:
        fail("cannot read '%s': %s" % (pvd, error))
    folder = os.path.dirname(os.path.abspath(pvd))
    times = {}
    for index, dataset in enumerate(root.iter("DataSet")):
        time_name, name, file = (dataset.get(key) for key in ("timestep", "name", "file"))
        if time_name is None or file is None:
            fail("'%s': DataSet %d lacks 'timestep' or 'file'" % (pvd, index))
        if name is None:
            name = os.path.splitext(os.path.basename(file))[0]
        times.setdefault(float(time_name), []).append(
            (time_name, name, os.path.join(folder, file)))
    if not times:
        fail("'%s' lists no data sets" % pvd)
    return times


def choose_time(times, request):
    ordered = sorted(times)
    if request == "first":
        return ordered[0]
    if request == "last":
        return ordered[-1]
    try:
        wanted = float(request)
    except ValueError:
        fail("--time takes 'first', 'last' or a number, not '%s'" % request)
    chosen = min(ordered, key=lambda t: abs(t - wanted))
    if abs(chosen - wanted) > 1e-9 * max(1.0, abs(wanted)):
        sys.stderr.write("renderCloud: no time %s written; the nearest is %s\n"
                         % (request, times[chosen][0][0]))
    return chosen


def attribute(source, name):
    """A one-value field-data attribute of the reader's output (e.g. 'spacing'), or None."""
    try:
        array = source.FieldData.GetArray(name)
        return None if array is None else array.GetRange(0)[0]
    except Exception:  # noqa: BLE001 - older or newer proxies: fall back to the bounds
        return None


def spacing_from_bounds(bounds, count):
    """Particle spacing estimated from the bounding box: volume (or area) per particle."""
    extents = sorted(max(bounds[2 * i + 1] - bounds[2 * i], 0.0) for i in range(3))
    if count < 2 or extents[2] == 0:
        return max(extents[2], 1e-3) * 0.05
    if extents[1] < 1e-9 * extents[2]:
        return extents[2] / count
    if extents[0] < 1e-9 * extents[2]:
        return math.sqrt(extents[1] * extents[2] / count)
    return (extents[0] * extents[1] * extents[2] / count) ** (1.0 / 3.0)


def array_range(source, field):
    array = source.PointData.GetArray(field)
    if array is None:
        return None
    return array.GetRange(-1 if array.GetNumberOfComponents() > 1 else 0)


def set_if_present(proxy, name, value):
    """Sets a property the running ParaView version has, quietly skipping one it lacks."""
    try:
        setattr(proxy, name, value)
        return True
    except (AttributeError, ValueError):
        return False


def set_window_location(proxy, location):
    # ParaView 5.10 on spells 'Upper Center', older versions 'UpperCenter'.
    if not set_if_present(proxy, "WindowLocation", location):
        set_if_present(proxy, "WindowLocation", location.replace(" ", ""))


def camera_frame(args, clouds_bounds):
    """(direction the camera looks in, view-up) for the chosen or default view."""
    if args.view_direction:
        direction = normalized(args.view_direction)
    elif args.clip_normal:
        direction = [-c for c in normalized(args.clip_normal)]
    else:
        extents = [clouds_bounds[2 * i + 1] - clouds_bounds[2 * i] for i in range(3)]
        thin = min(range(3), key=lambda i: extents[i])
        if extents[thin] < 1e-6 * max(extents):  # a flat (2D) case: look across its plane
            direction = [0.0, 0.0, 0.0]
            direction[thin] = -1.0
        else:
            direction = normalized([-0.55, 1.0, -0.45])  # front-right, from a little above
    if args.view_up:
        up = args.view_up
    else:
        up = [0.0, 0.0, 1.0]
        if abs(direction[2]) > 0.99:
            up = [0.0, 1.0, 0.0]
    if vector_norm(cross(direction, up)) < 1e-6:
        fail("--view-up is parallel to the view direction")
    return direction, up


def main(argv):
    args = parse_arguments(argv)
    pvd = args.pvd
    if os.path.isdir(pvd):
        found = sorted(f for f in os.listdir(pvd) if f.endswith(".pvd"))
        if not found:
            fail("no .pvd in '%s': run the solver first" % pvd)
        pvd = os.path.join(pvd, found[0])
    case = os.path.splitext(os.path.basename(pvd))[0]
    times = read_pvd(pvd)
    time = choose_time(times, args.time)
    entries = times[time]
    time_name = entries[0][0]
    if args.clouds:
        missing = sorted(set(args.clouds) - {name for _, name, _ in entries})
        if missing:
            fail("time %s has no cloud %s; it has: %s" % (
                time_name, ", ".join(missing), ", ".join(name for _, name, _ in entries)))
        entries = [entry for entry in entries if entry[1] in args.clouds]

    # Imported here so that --help and the argument checks work without a display.
    from paraview import simple
    simple._DisableFirstRenderCameraReset()

    view = simple.CreateView("RenderView")
    view.ViewSize = list(args.size)
    set_if_present(view, "UseColorPaletteForBackground", 0)
    set_if_present(view, "BackgroundColorMode", "Single Color")
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    set_if_present(view, "OrientationAxesLabelColor", [0.0, 0.0, 0.0])
    set_if_present(view, "OrientationAxesOutlineColor", [0.0, 0.0, 0.0])
    simple.SetActiveView(view)

    # Read every cloud, clip it, find its spacing and its range of the field.
    clouds = []
    for _, name, file in entries:
        if not os.path.isfile(file):
            fail("'%s' (cloud %s at time %s) is missing" % (file, name, time_name))
        reader = simple.XMLPolyDataReader(FileName=[file])
        reader.UpdatePipeline(time)
        info = reader.GetDataInformation()
        count = info.GetNumberOfPoints()
        spacing = attribute(reader, "spacing")
        source = reader
        if args.clip_normal:
            clip = simple.Clip(Input=reader)
            clip.ClipType = "Plane"
            clip.ClipType.Origin = list(args.clip_origin or [0.0, 0.0, 0.0])
            clip.ClipType.Normal = list(args.clip_normal)
            set_if_present(clip, "Invert", 1)  # keep the half behind the normal
            set_if_present(clip, "Crinkleclip", 1)  # whole particles, never cut vertices
            clip.UpdatePipeline(time)
            source = clip
        shown = source.GetDataInformation().GetNumberOfPoints()
        clouds.append({"name": name, "reader": reader, "source": source, "count": count,
                       "shown": shown, "spacing": spacing, "bounds": info.GetBounds(),
                       "range": array_range(source, args.field) if shown else None})
    if not any(cloud["shown"] for cloud in clouds):
        fail("nothing left to show at time %s (the clip removes every particle?)" % time_name)
    known = [cloud["spacing"] for cloud in clouds if cloud["spacing"] and cloud["spacing"] > 0]
    coloured = [cloud for cloud in clouds if cloud["range"] is not None]
    if not coloured:
        sys.stderr.write("renderCloud: warning: no cloud at time %s has the field '%s'; all "
                         "are grey\n" % (time_name, args.field))

    # The shared colour map and its range (set again after ColorBy, which may rescale it).
    lut = pwf = None
    if coloured:
        lut = simple.GetColorTransferFunction(args.field)
        set_if_present(lut, "AutomaticRescaleRangeMode", "Never")
        if args.colormap and not lut.ApplyPreset(args.colormap, True):
            sys.stderr.write("renderCloud: warning: no colour map '%s'; ParaView's "
                             "default kept\n" % args.colormap)
        pwf = simple.GetOpacityTransferFunction(args.field)
        if args.range:
            low, high = args.range
        elif args.field in FIXED_RANGES:
            low, high = FIXED_RANGES[args.field]
        else:
            low = min(cloud["range"][0] for cloud in coloured)
            high = max(cloud["range"][1] for cloud in coloured)
            if high <= low:
                pad = max(abs(low) * 0.01, 1e-12)
                low, high = low - pad, high + pad

    max_radius = 0.0
    for cloud in clouds:
        if not cloud["shown"]:
            continue
        display = simple.Show(cloud["source"], view)
        display.SetRepresentationType("Point Gaussian")
        spacing = cloud["spacing"] or (min(known) if known else
                                       spacing_from_bounds(cloud["bounds"], cloud["count"]))
        display.GaussianRadius = args.point_radius or 0.5 * spacing
        max_radius = max(max_radius, display.GaussianRadius)
        set_if_present(display, "ShaderPreset", "Sphere")
        set_if_present(display, "ScaleByArray", 0)
        if cloud["range"] is not None:
            array = cloud["source"].PointData.GetArray(args.field)
            if array.GetNumberOfComponents() > 1:
                simple.ColorBy(display, ("POINTS", args.field, "Magnitude"))
                lut.VectorMode = "Magnitude"
            else:
                simple.ColorBy(display, ("POINTS", args.field))
            display.LookupTable = lut
            set_if_present(display, "OpacityTransferFunction", pwf)
        else:
            display.ColorArrayName = ["POINTS", ""]  # solid colour (ColorBy(d, None) fails in 5.11)
            display.AmbientColor = GREY
            display.DiffuseColor = GREY
        print("renderCloud: %s: %d of %d particles shown, %s, sphere radius %.3g m" % (
            cloud["name"], cloud["shown"], cloud["count"],
            "coloured by " + args.field if cloud["range"] is not None else "grey (no %s)"
            % args.field, display.GaussianRadius), flush=True)

    if lut is not None:
        lut.RescaleTransferFunction(low, high)
        pwf.RescaleTransferFunction(low, high)
        bar = simple.GetScalarBar(lut, view)
        unit = UNITS.get(args.field)
        vector = any(cloud["source"].PointData.GetArray(args.field).GetNumberOfComponents() > 1
                     for cloud in coloured)
        title = (args.field + " magnitude") if vector else args.field
        bar.Title = title + (" (%s)" % unit if unit else "")
        bar.ComponentTitle = ""
        bar.TitleColor = [0.0, 0.0, 0.0]
        bar.LabelColor = [0.0, 0.0, 0.0]
        bar.TitleFontSize = 20
        bar.LabelFontSize = 18
        set_if_present(bar, "HorizontalTitle", 1)
        set_if_present(bar, "ScalarBarLength", 0.6)
        set_if_present(bar, "ScalarBarThickness", 20)
        set_if_present(bar, "RangeLabelFormat", "%-#.4g")
        set_if_present(bar, "AutomaticLabelFormat", 1)
        set_if_present(bar, "AddRangeLabels", 1)
        set_if_present(bar, "DrawTickMarks", 1)
        set_window_location(bar, "Any Location")
        bar.Position = [0.87, 0.12]
        bar.Visibility = 1

    text = simple.Text(Text=args.title or "%s   t = %s s" % (case, time_name))
    text_display = simple.Show(text, view)
    text_display.Color = [0.0, 0.0, 0.0]
    text_display.FontSize = 24
    set_window_location(text_display, "Upper Center")

    # Camera: fit the shown particles, looking along the chosen direction.
    bounds = [math.inf, -math.inf] * 3
    for cloud in clouds:
        if cloud["shown"]:
            b = cloud["source"].GetDataInformation().GetBounds()
            for i in range(3):
                bounds[2 * i] = min(bounds[2 * i], b[2 * i])
                bounds[2 * i + 1] = max(bounds[2 * i + 1], b[2 * i + 1])
    direction, up = camera_frame(args, bounds)
    right = normalized(cross(direction, up))
    screen_up = cross(right, direction)
    centre = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
    corners = [[bounds[i], bounds[2 + j], bounds[4 + k]] for i in (0, 1) for j in (0, 1)
               for k in (0, 1)]
    pad = 2.0 * max_radius
    width = max(dot(c, right) for c in corners) - min(dot(c, right) for c in corners) + pad
    height = (max(dot(c, screen_up) for c in corners)
              - min(dot(c, screen_up) for c in corners) + pad)
    diagonal = max(vector_norm([bounds[2 * i + 1] - bounds[2 * i] for i in range(3)]), 1e-6)
    view.CameraViewUp = list(screen_up)
    view.CameraParallelProjection = 0 if args.perspective else 1
    if args.perspective:
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[i] - 3.0 * diagonal * direction[i] for i in range(3)]
        simple.ResetCamera(view)
        zoom = args.zoom
    else:
        # Fit the clouds into the part of the image left of the legend and below the title:
        # x in [0.03, 0.84] of the width, y in [0.03, 0.90] of the height.
        aspect = float(args.size[0]) / args.size[1]
        scale = max(height / (2 * 0.87), width / (2 * 0.81 * aspect))
        shift_x = (0.5 - 0.435) * 2 * scale * aspect
        shift_y = (0.5 - 0.465) * 2 * scale
        focal = [centre[i] + shift_x * right[i] + shift_y * screen_up[i] for i in range(3)]
        view.CameraFocalPoint = focal
        view.CameraPosition = [focal[i] - 3.0 * diagonal * direction[i] for i in range(3)]
        view.CameraParallelScale = scale
        zoom = args.zoom
    if zoom != 1.0:
        simple.GetActiveCamera().Zoom(zoom)

    output = args.output or os.path.join(
        os.path.dirname(os.path.abspath(pvd)), "%s_%s_%s.png" % (case, args.field, time_name))
    simple.Render(view)
    if os.path.exists(output):
        os.remove(output)
    simple.SaveScreenshot(output, view, ImageResolution=list(args.size),
                          TransparentBackground=0)
    if not os.path.isfile(output):
        fail("ParaView wrote no '%s'" % output)
    # Flushed: pvpython may leave without flushing a redirected stdout.
    print("renderCloud: wrote %s (%s at t = %s s, %dx%d)" % (
        output, args.field, time_name, args.size[0], args.size[1]), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
