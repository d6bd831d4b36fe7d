"""The course design (机械原理课程设计): its table of crank positions and its export.

``positions`` the numbered and special crank positions, tabulated; ``plan`` which files
the course export writes, in which order, named how, checked before the first is written.
"""
