"""Shared look of the tutorials' ParaView renders (pvbatch scripts)."""


def style_scalar_bar(bar, title, fmt, position, length):
    """A horizontal black-on-white scalar bar at `position` (view fractions)."""
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = 20
    bar.LabelFontSize = 18
    bar.RangeLabelFormat = fmt
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Any Location"
    bar.Position = list(position)
    bar.ScalarBarLength = length


def show_points(source, view, field, point_size):
    """Shows a point set as spheres coloured by a point field (Viridis);
    returns the display and the colour map."""
    from paraview.simple import ColorBy, GetColorTransferFunction, Show
    display = Show(source, view)
    display.SetRepresentationType("Points")
    display.PointSize = point_size
    display.RenderPointsAsSpheres = 1
    ColorBy(display, ("POINTS", field))
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    return display, lut


def white_view(size):
    """A render view of `size` pixels on a white background, no axes."""
    from paraview.simple import CreateView
    view = CreateView("RenderView")
    view.ViewSize = list(size)
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0   # ParaView >= 5.10
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 0
    return view
