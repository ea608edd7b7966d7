# `cmake --install`: the layout app/install_paths.h looks for, relative to the programs' folder.
#   bin/                         rasterlab, rasterlab-cli
#   share/rasterlab/             translations/*.qm, lessons/NAME/
#   share/doc/rasterlab/         the user guides and their pictures, the command-line, lesson
#                                file and file format references, examples/, copyright, changelog
#   share/man/man1/              rasterlab.1.gz, rasterlab-cli.1.gz
#   share/applications/, share/metainfo/, share/mime/packages/, share/icons/hicolor/
set(data "${RASTERLAB_DATA_BUILD_DIR}")
set(app_id org.rasterlab.RasterLab)

install(TARGETS rasterlab rasterlab-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${RASTERLAB_QM_FILES} DESTINATION ${CMAKE_INSTALL_DATADIR}/rasterlab/translations)
install(DIRECTORY resources/lessons DESTINATION ${CMAKE_INSTALL_DATADIR}/rasterlab)

install(FILES docs/guide.en.md docs/guide.pt_BR.md docs/command-line.md docs/lesson-files.md
              docs/file-formats.md
        DESTINATION ${RASTERLAB_INSTALL_DOCDIR})
install(DIRECTORY docs/images/tour DESTINATION ${RASTERLAB_INSTALL_DOCDIR}/images)
install(DIRECTORY docs/examples DESTINATION ${RASTERLAB_INSTALL_DOCDIR})
install(FILES data/debian/copyright "${data}/changelog.gz" DESTINATION ${RASTERLAB_INSTALL_DOCDIR})
install(FILES "${data}/rasterlab.1.gz" "${data}/rasterlab-cli.1.gz"
        DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

install(FILES data/${app_id}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES "${data}/${app_id}.metainfo.xml" DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES data/rasterlab-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
        RENAME rasterlab.xml)
install(FILES data/icons/rasterlab.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
if(RASTERLAB_PNG_ICONS)
    foreach(size IN LISTS RASTERLAB_ICON_SIZES)
        install(FILES "${data}/icons/${size}x${size}/rasterlab.png"
                DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
    endforeach()
endif()
