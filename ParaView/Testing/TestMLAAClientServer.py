# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Client and server: pvpython connected to a pvserver of one or more ranks renders the MLAA
view's scene (TestMLAAView.py's) on the server, with MLAA and with DLAA, and its screenshots equal
those of pvpython's built-in session within 2/255; so do those the client renders itself from the
geometry the server sends it (ParaView's choice for small data).

Run by ParaView's client-server test driver, smTestDriver, which starts the server (under mpiexec,
SMTESTDRIVER_MPI_NUMPROCS ranks, on a port the server picks), then this script in pvpython with
the server's address (--url), and stops the server when the client is done:

    smTestDriver --server pvserver --client pvpython --dr TestMLAAClientServer.py
        --plugin MLAA.so --output-dir DIR --ranks N

The plugin is loaded on both sides, as users must: LoadPlugin(..., remote=True) on the server and
remote=False on the client."""

import os

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview import servermanager as sm  # noqa: E402
from paraview.simple import *  # noqa: E402,F403

# The server's address, as smTestDriver gave it to pvpython (--url=cs://HOST:PORT). pvpython does
# not connect by itself: the script starts in a built-in session.
url = sm.vtkRemotingCoreConfiguration.GetInstance().GetServerURL()
t.check(url.startswith("cs://"), "the client has the server's address (%s)" % url)
host, port = url[len("cs://"):].rsplit(":", 1)
t.check(not sm.ActiveConnection.IsRemote(), "the script starts in a built-in session")


def loaded_plugins(information):
    return [information.GetPluginName(i) for i in range(information.GetNumberOfPlugins())
            if information.GetPluginLoaded(i)]


def render(session, where="server"):
    """The scene in a new MLAA view of the active session, with UseMLAA off, with MLAA and with
    DLAA: the screenshots, as (y, x, RGB) rows by name. In client-server, rendered `where` says:
    on the server, or on the client from the geometry the server sends it."""
    view = CreateView("MLAARenderView")
    size, sphere = t.show_view_scene(view)
    # The data's size (in MB) above which the server renders: 0, always; 1000, never here.
    view.RemoteRenderThreshold = 0 if where == "server" else 1000
    view.UseFXAA = 0
    if args.ranks > 1 and session == "client-server" and where == "server":
        t.check_split(sphere, args.ranks, "sphere")
    screenshots = {}
    for name, mlaa, dlaa in (("off", 0, 0), ("mlaa", 1, 0), ("dlaa", 0, 1)):
        view.UseMLAA = mlaa
        view.UseDLAA = dlaa
        # (Not simple.Render: the first one in a process resets the camera.)
        path = os.path.join(args.output_dir, "%s-%s-%s.png" % (session, where, name))
        SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=0)
        if session == "client-server":
            remote = view.GetClientSideObject().GetUseDistributedRenderingForRender()
            t.check(remote == (where == "server"), "%s: the %s rendered the image" % (name, where))
        screenshots[name] = t.read_png(path)[:, :, :3]
    Delete(view)
    return screenshots


# The built-in session first: the server waits for its client meanwhile, and stops once the
# client disconnects.
t.load_plugin(args.plugin, globals())
built_in = render("builtin")

Connect(host, int(port))
t.check(sm.ActiveConnection.IsRemote(), "connected to the server at %s:%s" % (host, port))
t.check(sm.ActiveConnection.GetNumberOfDataPartitions() == args.ranks,
        "the server runs on %d rank(s)" % args.ranks)
LoadPlugin(args.plugin, remote=True, ns=globals())
LoadPlugin(args.plugin, remote=False, ns=globals())
manager = sm.vtkSMProxyManager.GetProxyManager().GetPluginManager()
on_client = loaded_plugins(manager.GetLocalInformation())
on_server = loaded_plugins(manager.GetRemoteInformation(sm.ActiveConnection.Session))
t.check("MLAA" in on_client and "MLAA" in on_server,
        "the plugin is loaded on the client and on the server (client: %s; server: %s)"
        % (on_client, on_server))
results = {where: render("client-server", where) for where in ("server", "client")}
Disconnect()

for where, screenshots in results.items():
    for name in ("off", "mlaa", "dlaa"):
        difference = t.max_difference(screenshots[name], built_in[name])
        t.check(difference <= 2, "%s, rendered on the %s: the screenshot equals the built-in "
                "session's within 2/255 (max difference %d)" % (name, where, difference))
    for name in ("mlaa", "dlaa"):
        changed = (screenshots[name] != screenshots["off"]).any(axis=2).sum()
        t.check(changed > 200, "%s, rendered on the %s: %d edge pixels are antialiased"
                % (name, where, changed))
