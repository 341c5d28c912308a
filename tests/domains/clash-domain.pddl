; A type and an object share a name (legal PDDL: types and objects live in separate namespaces):
; the objects "cup" and "thing" are also types, and "place" is an object of type place.
(define (domain clash)
  (:requirements :strips :typing)
  (:types place thing - object cup - thing)
  (:predicates (at ?t - thing ?p - place) (holding ?t - thing) (free))
  (:action pick :parameters (?t - thing ?p - place)
    :precondition (and (at ?t ?p) (free))
    :effect (and (not (at ?t ?p)) (not (free)) (holding ?t)))
  (:action drop :parameters (?t - thing ?p - place)
    :precondition (holding ?t)
    :effect (and (at ?t ?p) (free) (not (holding ?t)))))
