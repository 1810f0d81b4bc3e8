# bin/paraview.conf: how ParaView 5.11 finds plugins by name. pvpython,
# pvbatch and paraview read <their bin>/paraview.conf at start (the first
# one only), a list of plugin XML files, relative to that bin folder; each
# XML names plugins that ParaView then finds in <XML folder>/<Name>/<Name>.so.
# Those become loadable by name (LoadDistributedPlugin('VTKShadow') in
# Python, the GUI's plugin manager) without PV_PLUGIN_PATH. Debian's
# ParaView ships no paraview.conf, so installing vtkshadow-paraview into
# ParaView's prefix (/usr) adds one listing only vtkshadow.plugins.xml.
# (ParaView's own paraview_plugin_write_conf would write absolute paths
# into the private ParaView prefix of scripts/install-paraview.sh, which
# the package must not name.)
set(VTKSHADOW_PARAVIEW_CONF "${CMAKE_CURRENT_BINARY_DIR}/conf/paraview.conf")
file(RELATIVE_PATH vtkshadow_conf_entry "/prefix/${CMAKE_INSTALL_BINDIR}"
  "/prefix/${VTKSHADOW_PARAVIEW_LIBDIR}/${PARAVIEW_PLUGIN_SUBDIR}/vtkshadow.plugins.xml")
file(WRITE "${VTKSHADOW_PARAVIEW_CONF}" "${vtkshadow_conf_entry}\n")
install(FILES "${VTKSHADOW_PARAVIEW_CONF}"
  DESTINATION "${CMAKE_INSTALL_BINDIR}"
  COMPONENT paraview)
