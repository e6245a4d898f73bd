"""The five machines of issue 21: the 11/23 and four LSI-11/03 axis controllers in
lock-step on one plant (docs/controllers.md): the coordinator, the members' SIMH
settings, the scripted run of all five, the interactive launcher."""
