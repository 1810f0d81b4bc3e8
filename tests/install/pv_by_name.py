"""pvpython/pvbatch with no PV_PLUGIN_PATH: the installed VTKShadow plugin
loads by name (ParaView finds it through bin/paraview.conf and
vtkshadow.plugins.xml) and its view exists. Prints the file it loaded;
exits 1 when it is not the expected one (argv[1]; scripts/install-paraview.sh's
private ParaView reaches it through links, so compared resolved) or
anything fails.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import CreateView, LoadDistributedPlugin

expected = sys.argv[1]
LoadDistributedPlugin("VTKShadow", remote=False)
info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager().GetLocalInformation()
loaded = [info.GetPluginFileName(i) for i in range(info.GetNumberOfPlugins())
          if info.GetPluginName(i) == "VTKShadow"]
print("VTKShadow loaded from", loaded)
view = CreateView("RenderViewWithShadows")
print("view technique", view.ShadowTechnique)
sys.exit(0 if [os.path.realpath(f) for f in loaded] == [expected] else 1)
