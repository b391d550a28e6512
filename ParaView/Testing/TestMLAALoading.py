# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Loading without LoadPlugin: with PV_PLUGIN_PATH naming the plugin's folder, pvbatch loads it
at start-up and paraview.simple offers the filter and the view."""

import mlaa_pvtest as t

args = t.parse_arguments()

import paraview.simple as simple  # noqa: E402

t.check(hasattr(simple, "MLAAAntialiasing"), "paraview.simple has MLAAAntialiasing")
view = simple.CreateView("MLAARenderView")
t.check(view.UseMLAA == 1, "CreateView('MLAARenderView') makes the MLAA view")
