"""The whole course design in one go: ``shaper course`` and File › Export course design…"""
